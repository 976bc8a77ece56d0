#pragma once
// The fields of one registered solver at several output times, from one start:
// what an animation and the measurements of a wave's evolution need
// (shockgas/compare/field_evolution.hpp).
//
// At t = 0 the fields are the cell averages of the initial data. A solver that
// evaluates at any t directly (SolverInfo::direct_in_time: Hopf-Lax, Hopf-Cole)
// is evaluated once per time from the initial data. A marching solver is
// solved from one output time to the next, restarting from its own cell
// averages: the piecewise-constant field with those averages has exactly those
// cell averages again, so a one-step scheme (Godunov, MUSCL-Hancock, the
// pressureless scheme) gives what it would give had it stopped at each output
// time on its way; a multistep integrator (CVODE's BDF) restarts its history at
// each output time, within its tolerance rtol. The cost is about one solve to
// the last time, not one per time.
#include <string>
#include <vector>

#include "shockgas/continuum/field.hpp"
#include "shockgas/continuum/params.hpp"
#include "shockgas/core/initial_condition.hpp"
#include "shockgas/core/progress.hpp"

namespace shockgas::continuum {

// The fields of solver `name` at each of `times` (non-decreasing, >= 0), one
// result per time, result[k].t = times[k]. Throws InputError for an unknown name,
// times out of order or negative, or parameters outside the solver's range;
// RunError as solve().
std::vector<ContinuumResult> solve_at_times(const std::string& name, const InitialField& f,
                                            const ContinuumParams& p, const std::vector<double>& times,
                                            const ProgressCallback& progress = {});

// The piecewise-constant field on [0, r.length) whose cell averages are r.v and
// r.rho (r.rho empty: density 1): the state from which a marching solver continues.
InitialField piecewise_constant_field(const ContinuumResult& r);

}  // namespace shockgas::continuum
