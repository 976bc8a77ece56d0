#pragma once
// Burgers + continuity by Godunov finite volume, first and second order
// (godunov_scheme.hpp with the physics of burgers_physics.hpp).
#include "shockgas/continuum/field.hpp"
#include "shockgas/continuum/params.hpp"
#include "shockgas/core/initial_condition.hpp"
#include "shockgas/core/progress.hpp"

namespace shockgas::continuum {

// Solves v_t + (v^2/2)_x = 0, rho_t + (rho v)_x = 0 from the cell averages
// cell_averages(f, p.cells) to t_end on [0, f.length) with p.boundary.
//  * order 1: Godunov with the exact Riemann flux, solver name "godunov";
//  * order 2: MUSCL-Hancock with limiter p.limiter, solver name "godunov2".
// dt = p.cfl dx / max|v|, the last step landing on t_end. Uses p.cells, p.cfl
// (in (0, 1] unless p.allow_unstable), p.limiter, p.boundary.
// Returns x (cell centres), v, rho (cell averages) at t_end and stats["steps"].
// Throws InputError before the run for a bad parameter or initial datum (naming
// the key), RunError if a value becomes non-finite (naming solver, time, cell).
ContinuumResult solve_godunov(const InitialField& f, const ContinuumParams& p, double t_end, int order,
                              const ProgressCallback& progress = {});

}  // namespace shockgas::continuum
