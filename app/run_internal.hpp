#pragma once
// The steps of run_scene (run.cpp), shared with a sweep (run_sweep.cpp).
#include <filesystem>
#include <functional>
#include <string>

#include "output_layout.hpp"
#include "progress_bar.hpp"
#include "run_results.hpp"
#include "shockgas/app/run.hpp"

namespace shockgas::app {

// The scene's initial condition; an InputError located at the scene's key.
InitialCondition build_initial(const Scene& scene);

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

// One scene (no sweep) into dir, after preflight(); each part also handed to
// `also`, if given. Returns what a sweep keeps of it.
VariantResult run_single(const Scene& scene, const InitialCondition& initial,
                         const std::filesystem::path& dir, const RunOptions& options,
                         const PartSink& also = {}, const EnsembleSource& source = {});

// A [sweep] scene: each variant into dir/<k>-<label>/, the side-by-side table and plots into dir.
std::string run_sweep(const Scene& scene, const std::filesystem::path& dir, const RunOptions& options,
                      const EnsembleSource& source = {});

// A run on the processes of an MPI job, or of a slice of the realizations (a
// shard): parallel_run.cpp.
// So does a run that keeps checkpoints (checkpointer.hpp): its records are
// saved as they finish.
bool runs_in_parallel(const RunOptions& options);
bool keeps_checkpoints(const RunOptions& options);
std::string run_parallel(const Scene& scene, const std::filesystem::path& dir, const RunOptions& options);

}  // namespace shockgas::app
