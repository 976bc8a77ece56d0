#pragma once
// What the stages of a run share: the scene, the open result file, the summary
// and the results that later stages (the comparison) need from earlier ones.
#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

#include "shockgas/app/hdf5_file.hpp"
#include "shockgas/app/progress_bar.hpp"
#include "shockgas/app/scene.hpp"
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
  std::optional<Bodies> final_bodies;                    // particles at t_end (realization 0)
  std::vector<double> t_series, T_series;                // ensemble-mean T(t)
  std::vector<double> hist_z, hist_t, hist_density;      // ensemble-mean scaled histogram (rows: t)
  std::vector<continuum::ContinuumResult> continuum;     // one per solver
  std::vector<std::string> report;                       // lines of report.md
};

// The stages, in order; each writes its part of result.h5 and summary.json.
void run_initial_stage(RunState& state);
void run_particles_stage(RunState& state);
void run_continuum_stage(RunState& state);
void run_compare_stage(RunState& state);

}  // namespace shockgas::app
