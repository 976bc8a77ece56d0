#pragma once
// The steps of run_scene (run.cpp), shared with a sweep (run_sweep.cpp).
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "shockgas/app/directory/run_directory.hpp"
#include "shockgas/app/output/output_layout.hpp"
#include "shockgas/app/output/run_results.hpp"
#include "shockgas/app/run/progress_bar.hpp"
#include "shockgas/app/run/run_options.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::app {

// An input error located where the scene set its key (a file line or a --set);
// errors that carry their own place (a line of a bodies file) keep it.
InputError located(const InputError& e, const Scene& scene);

// The scene's initial condition; an InputError located at the scene's key.
// Realization 0's bodies are held only where a continuum needs them (or they
// cannot be drawn on the fly); the particles and the writers draw them in chunks.
InitialCondition build_initial(const Scene& scene);

// The progress of a continuum solve (solver `name`), which fails it with a
// RunError once it has taken longer than the run's wall limit
// (particles.max_wall_seconds, if set): a solve obeys the limit a realization
// obeys, at its progress points.
ProgressCallback wall_limited(const Scene& scene, const std::string& name, ProgressCallback report);

// Each continuum solver's own limits (its registered preflight) and a requested
// particle schedule, checked before any work; InputError located at the key.
void preflight(const Scene& scene, const InitialCondition& initial);

// Receives each part of a run as soon as it is computed, before the records it
// holds are released: the result files are written so, and a host may keep the
// outputs in memory the same way (captured_outputs.hpp).
using PartSink = std::function<void(const RunResults&, Part)>;

// The parts of one scene (no sweep) in order, after preflight(), each handed to
// sink when done; returns the results (records released, as run_single keeps them).
// source: where its particle ensemble comes from, if not run here.
RunResults compute_parts(const Scene& scene, const InitialCondition& initial, ProgressBar& progress,
                         const PartSink& sink, const EnsembleSource& source = {});

// One scene (no sweep) into dir (existing and empty), after preflight():
// result.h5, summary.json, report.md, the plots, manifest.json; each part also
// handed to `also`, if given. Returns what a sweep keeps of it.
VariantResult run_single(const Scene& scene, const InitialCondition& initial,
                         const std::filesystem::path& dir, const RunOptions& options,
                         const PartSink& also = {}, const EnsembleSource& source = {});

// The variants of a [sweep] scene, each valid, its initial condition built and
// its solvers' limits checked, before any work.
struct SweepPlan {
  std::vector<Scene> variants;
  std::vector<std::optional<InitialCondition>> initial;  // released as each variant finishes
};
SweepPlan plan_sweep(const Scene& scene);

// The plots of a result directory, with its animation when asked: one phase of
// progress ("plots", "plots, animation"), drawn by one process, what it says
// told after it (plots.hpp); within as there.
void draw_plots(const std::filesystem::path& dir, bool animation, ProgressBar& progress,
                const std::string& within = "");

// A [sweep] scene into dir (existing and empty): each variant into
// dir/<k>-<label>/, then the side-by-side table, plots and manifest into dir.
void run_sweep(const Scene& scene, SweepPlan& plan, const std::filesystem::path& dir,
               const RunOptions& options, const EnsembleSource& source = {});

// Runs write(dir.staging()) and moves the staging directory into place (dir:
// made before any work, run_directory.hpp); returns out, the target as given.
// An InputError from write is located at the scene's key.
std::string into_run_directory(RunDirectory& dir, const std::filesystem::path& out, const Scene& scene,
                               const RunOptions& options,
                               const std::function<void(const std::filesystem::path& staging)>& write);

}  // namespace shockgas::app
