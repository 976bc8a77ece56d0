#pragma once
// One entry point for every registered continuum solver (registry.hpp), by name:
// what a scene's continuum.solvers list selects.
#include <string>

#include "shockgas/continuum/field.hpp"
#include "shockgas/continuum/params.hpp"
#include "shockgas/core/progress.hpp"

namespace shockgas::continuum {

// Runs the registered solver `name` from f to t_end on p.cells cells and times
// it (wall_seconds); result.solver = name. Throws InputError for an unknown name
// or parameters outside the solver's range, RunError if the solver fails or
// produces a non-finite value.
// An abort request (shockgas/core/interrupt.hpp) stops it at its next progress point,
// throwing Interrupted.
ContinuumResult solve(const std::string& name, const InitialField& f, const ContinuumParams& p, double t_end,
                      const ProgressCallback& progress = {});

}  // namespace shockgas::continuum
