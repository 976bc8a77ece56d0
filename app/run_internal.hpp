#pragma once
// The steps of run_scene (run.cpp), shared with a sweep (run_sweep.cpp).
#include <filesystem>
#include <string>

#include "run_results.hpp"
#include "shockgas/app/run.hpp"

namespace shockgas::app {

// The scene's initial condition; an InputError located at the scene's key.
InitialCondition build_initial(const Scene& scene);

// Each continuum solver's own limits (its registered preflight) and a requested
// particle schedule, checked before any work; InputError located at the key.
void preflight(const Scene& scene, const InitialCondition& initial);

// One scene (no sweep) into dir, after preflight(); returns what a sweep keeps
// of it. source: where its particle ensemble comes from, if not run here.
VariantResult run_single(const Scene& scene, const InitialCondition& initial,
                         const std::filesystem::path& dir, const RunOptions& options,
                         const EnsembleSource& source = {});

// A [sweep] scene: each variant into dir/<k>-<label>/, the side-by-side table and plots into dir.
std::string run_sweep(const Scene& scene, const std::filesystem::path& dir, const RunOptions& options,
                      const EnsembleSource& source = {});

// A run on the processes of an MPI job, or of a slice of the realizations (a
// shard): parallel_run.cpp.
bool runs_in_parallel(const RunOptions& options);
std::string run_parallel(const Scene& scene, const std::filesystem::path& dir, const RunOptions& options);

}  // namespace shockgas::app
