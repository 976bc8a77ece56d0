#pragma once
// One entry point for every continuum solver, by name: what a scene's
// continuum.solvers list selects.
#include <string>

#include "shockgas/continuum/field.hpp"
#include "shockgas/continuum/params.hpp"
#include "shockgas/core/progress.hpp"

namespace shockgas::continuum {

// Runs solver `name` ("godunov", "godunov2", "pressureless", "hopf_lax",
// "hopf_cole", "cvode", "arkode") from f to t_end on p.cells cells and times it
// (wall_seconds). Throws InputError for an unknown name or parameters outside
// the solver's range, RunError if the solver fails or produces a non-finite value.
ContinuumResult solve(const std::string& name, const InitialField& f, const ContinuumParams& p, double t_end,
                      const ProgressCallback& progress = {});

}  // namespace shockgas::continuum
