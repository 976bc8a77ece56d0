#pragma once
// Viscous Burgers + continuity by the method of lines on SUNDIALS:
//
//     v_t + (v^2/2)_x = nu v_xx,        rho_t + (rho v)_x = 0      on a periodic grid.
//
// Semi-discretisation (finite volume on cell averages, conservative: sum v_i and
// sum rho_i change only by rounding):
//  * advection of v: fourth-order central, F_{i+1/2} = f(v_{i+1/2}) with the face value
//    v_{i+1/2} = (7 (v_i + v_{i+1}) - (v_{i-1} + v_{i+2})) / 12 and f = burgers_flux;
//    no upwinding, so the viscous shock must be resolved (see resolution below);
//  * diffusion of v: fourth-order, nu (-v_{i+2} + 16 v_{i+1} - 30 v_i + 16 v_{i-1} - v_{i-2}) / 12 h^2;
//  * mass: first-order upwind flux v_{i+1/2} rho_upwind (the density has no
//    viscosity and piles up in the shock, where a central flux would oscillate).
// The state is interleaved, y = (v_0, rho_0, v_1, rho_1, ...), so the Jacobian is
// banded with half-bandwidth 5 apart from the periodic corners.
//
// Integrators:
//  * cvode: BDF (orders 1-5), Newton-Krylov: SPGMR preconditioned (left) by
//    CVBandPre, a band LU of the difference-quotient Jacobian without the periodic
//    corners; GMRES takes care of the corners.
//  * arkode: ARKStep IMEX (the default ARK 4(3) additive pair), advection of v and rho
//    explicit, diffusion implicit and linear (one Newton iteration per stage), SPGMR
//    with ARKBandPre.
// Tolerances: relative p.rtol, absolute atol = p.rtol * max(max|v0|, max rho0) on every
// component (one scale for the whole state).
//
// Resolution: the central advection needs the viscous shock width 4 nu / Dv
// (Dv = max v0 - min v0 bounds every jump) to span at least two cells:
// Dv h / nu <= 2, else InputError on continuum.cells (continuum.allow_unstable
// runs it anyway). The spatial error is O((Dv h / nu)^4) relative in the shock.
#include <cstddef>
#include <span>

#include "shockgas/continuum/field.hpp"
#include "shockgas/continuum/params.hpp"
#include "shockgas/continuum/registry.hpp"
#include "shockgas/core/initial_condition.hpp"
#include "shockgas/core/progress.hpp"

namespace shockgas::continuum {

// The semi-discrete right-hand side, split as the IMEX integrator needs it.
struct ViscousBurgersGrid {
  std::size_t cells = 0;  // number of cells (the state has 2 cells components)
  double h = 0;           // cell width [length]
  double nu = 0;          // viscosity [length^2/time]
};

// ydot = advection of v and transport of rho (the explicit part).
void viscous_advection_rhs(const ViscousBurgersGrid& g, std::span<const double> y, std::span<double> ydot);
// ydot = viscous term of v, 0 for rho (the implicit part).
void viscous_diffusion_rhs(const ViscousBurgersGrid& g, std::span<const double> y, std::span<double> ydot);
// ydot = both.
void viscous_burgers_rhs(const ViscousBurgersGrid& g, std::span<const double> y, std::span<double> ydot);

// The solvers: cell averages of v and rho at t_end on p.cells cells.
// Throw InputError for nu <= 0 (continuum.nu), t_end < 0 (continuum.t_end), too few
// cells (continuum.cells); RunError naming the solver, cell and time if a value turns
// non-finite, and naming the SUNDIALS call if the integrator fails.
// stats: "steps", "rhs_evaluations" (cvode; arkode: "rhs_explicit", "rhs_implicit",
// "step_attempts"), "nonlinear_iterations", "linear_iterations", "error_test_failures",
// "preconditioner_setups".
ContinuumResult solve_cvode(const InitialField& f, const ContinuumParams& p, double t_end,
                            const ProgressCallback& progress = {});
ContinuumResult solve_arkode(const InitialField& f, const ContinuumParams& p, double t_end,
                             const ProgressCallback& progress = {});

// Their registrations (registry.hpp).
SolverInfo cvode_solver();
SolverInfo arkode_solver();

}  // namespace shockgas::continuum
