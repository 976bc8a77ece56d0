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

// One scene (no sweep) into dir, after preflight(); returns what a sweep keeps of it.
VariantResult run_single(const Scene& scene, const InitialCondition& initial,
                         const std::filesystem::path& dir, const RunOptions& options);

// A [sweep] scene: each variant into dir/<k>-<label>/, the side-by-side table and plots into dir.
std::string run_sweep(const Scene& scene, const std::filesystem::path& dir, const RunOptions& options);

}  // namespace shockgas::app
