#pragma once
// What the stages of a run share: the scene, the open result file, the summary
// and the results that later stages (the comparison) need from earlier ones.
#include <nlohmann/json.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "shockgas/app/hdf5_file.hpp"
#include "shockgas/app/progress_bar.hpp"
#include "shockgas/app/run.hpp"
#include "shockgas/app/scene.hpp"
#include "shockgas/compare/particle_analysis.hpp"
#include "shockgas/continuum/field.hpp"
#include "shockgas/core/bodies.hpp"

namespace shockgas::app {

struct RunState {
  RunState(const Scene& s, Hdf5File& file, nlohmann::ordered_json& sum, ProgressBar& bar)
      : scene(s), h5(file), summary(sum), progress(bar) {}

  const Scene& scene;
  Hdf5File& h5;
  nlohmann::ordered_json& summary;
  ProgressBar& progress;

  // Filled by the stages, read by later ones.
  Bodies initial_bodies;                                 // realization 0
  std::optional<Bodies> final_bodies;                    // particles at final_time (realization 0)
  double final_time = 0;                                 // t_end, or earlier if the run stopped early
  std::vector<double> t_series, T_series;                // ensemble-mean T(t)
  compare::ZHistogram histogram;                         // ensemble-mean scaled histogram (rows: t)
  std::vector<continuum::ContinuumResult> continuum;     // one per solver
  std::vector<std::string> report;                       // lines of report.md
};

// The stages, in order; each writes its part of result.h5 and summary.json.
void run_initial_stage(RunState& state);
void run_particles_stage(RunState& state);
void run_analysis_stage(RunState& state);  // cooling law and velocity distribution of the particles
void run_continuum_stage(RunState& state);
void run_compare_stage(RunState& state);

// A number for report.md: 4 significant digits ("nan" stays "nan").
std::string brief(double value);

// Runs each continuum solver's own input checks (a zero-length solve); throws InputError.
void preflight(const Scene& scene);

// result.h5 and summary.json of one directory (created here; InputError if it
// cannot be): written under temporary names, renamed by commit(); removed if
// the run fails (destructor) or is interrupted (SIGINT, SIGTERM). Nests.
class PartialOutputs {
 public:
  explicit PartialOutputs(const std::filesystem::path& dir);
  ~PartialOutputs();
  PartialOutputs(const PartialOutputs&) = delete;
  PartialOutputs& operator=(const PartialOutputs&) = delete;
  const std::string& h5_path() const { return h5_tmp_; }  // where to write result.h5 now
  // Writes summary.json and renames both files to their final names.
  void commit(const nlohmann::ordered_json& summary);

 private:
  std::filesystem::path dir_;
  std::string h5_tmp_, json_tmp_;
};

// One scene (no sweep) into dir, after preflight(); returns dir.
std::string run_single(const Scene& scene, const std::filesystem::path& dir, const RunOptions& options);
// A [sweep] scene: each variant into dir/<k>-<label>/, the side-by-side table and plots into dir.
std::string run_sweep(const Scene& scene, const std::filesystem::path& dir, const RunOptions& options);
// Version, commit, time, scene text and resolved parameters as attributes of "/".
void write_provenance(Hdf5File& h5, nlohmann::ordered_json& summary, const Scene& scene);

}  // namespace shockgas::app
