#pragma once
// Burgers + continuity by Godunov finite volume, first and second order
// (godunov_scheme.hpp with the physics of burgers_physics.hpp).
#include "shockgas/continuum/field.hpp"
#include "shockgas/continuum/params.hpp"
#include "shockgas/continuum/registry.hpp"
#include "shockgas/core/initial_condition.hpp"
#include "shockgas/core/progress.hpp"

namespace shockgas::continuum {

// Solves v_t + (v^2/2)_x = 0, rho_t + (rho v)_x = 0 from the cell averages
// cell_averages(f, p.cells) to t_end on [0, f.length) with p.boundary.
//  * order 1: Godunov with the exact Riemann flux, registered as godunov;
//  * order 2: MUSCL-Hancock with limiter p.limiter, registered as godunov2.
// dt = p.cfl dx / max|v|, the last step landing on t_end. Uses p.cells, p.cfl
// (in (0, 1] unless p.allow_unstable), p.limiter, p.boundary.
//
// Order 1 and the density at a sonic point (measured in
// tests/continuum/test_godunov_sonic.cpp). Where smooth data pass through v = 0
// with v_x = a > 0, the face between cells v_{j-1} < 0 < v_j is a transonic fan
// whose exact mass flux is 0 (as is rho v at the sonic point itself), and each
// of the two cells empties only through its other face, from its own state.
// They evolve as isolated blocks of uniform velocity, which cannot expand
// (semi-discrete, k = j-1, j):
//     d|v_k|/dt = -v_k^2 / (2 dx),   d rho_k/dt = -rho_k |v_k| / dx
//     =>  rho_k(t) = rho_k(0) / (1 + |v_k(0)| t / (2 dx))^2,
// against rho0 / (1 + a t) on the exact sonic characteristic. As
// |v_k(0)| = a |x_k - x_s| is a dx times a distance in cells, the error is O(1)
// on every grid: order 0 in the maximum norm, order 1 in L1 (two cells of
// width dx and a tail that decays with the distance in cells). A cell centred
// on the sonic point keeps its density for ever. No flux at that one face
// removes it: the upwind fluxes rho_i v_i of the faces on either side take v
// half a cell upstream, nearer the sonic point on both sides, and v has the
// O(dx) sonic kink of first-order upwind schemes, an O(1) error in v_x
// (van Leer, Lee & Powell, "Sonic-point capturing", AIAA 89-1945, 1989).
// Order 2 builds face values from slopes and converges there (order 1 at the
// two cells, 2 in L1).
//
// Returns x (cell centres), v, rho (cell averages) at t_end and stats["steps"].
// Throws InputError before the run for a bad parameter or initial datum (naming
// the key), RunError if a value becomes non-finite (naming solver, time, cell).
ContinuumResult solve_godunov(const InitialField& f, const ContinuumParams& p, double t_end, int order,
                              const ProgressCallback& progress = {});

// The registrations of the two orders (registry.hpp).
SolverInfo godunov_solver();
SolverInfo godunov2_solver();

}  // namespace shockgas::continuum
