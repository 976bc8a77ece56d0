#pragma once
// The pressureless gas (sticky particles' continuum) by first-order Godunov
// finite volume (godunov_scheme.hpp with pressureless_physics.hpp).
#include "shockgas/continuum/field.hpp"
#include "shockgas/continuum/params.hpp"
#include "shockgas/continuum/registry.hpp"
#include "shockgas/core/initial_condition.hpp"
#include "shockgas/core/progress.hpp"

namespace shockgas::continuum {

// Solves rho_t + (rho u)_x = 0, (rho u)_t + (rho u^2)_x = 0 from the cell
// averages cell_averages(f, p.cells) (m = rho v per cell) to t_end on
// [0, f.length) with p.boundary, dt = p.cfl dx / max|u|, p.cfl in (0, 1] unless
// p.allow_unstable (the Godunov flux moves a cell's mass at most one cell per step,
// which keeps rho >= 0 and u within its initial range). Mass and momentum are
// conserved to rounding on a periodic domain; clusters are delta-shocks moving at
// their momentum / mass. Registered as pressureless.
// Accuracy (measured, tests/continuum/test_pressureless.cpp): first order in L1
// for smooth data. Both characteristic fields of the gas are linearly degenerate,
// so nothing re-sharpens a cluster: a first-order scheme smears a delta-shock
// like a contact, over ~sqrt(dx |u| t) (about 15 cells at 1024 cells, t = 0.5),
// while its peak and its momentum / mass stay on the exact cluster. The velocity
// error after shocks therefore falls only as dx^0.64 (sine, t = 0.5), against
// dx^1 for solve_godunov, whose Burgers shock stays two cells wide. At a sonic
// point of smooth data the two cells beside the transonic face are isolated
// blocks, as in solve_godunov (godunov.hpp): u_k stays u_k(0) and
// rho_k(t) = rho_k(0) exp(-|u_k(0)| t / dx), an O(1) density error on every grid
// (order 0 in the maximum norm, 1 in L1; tests/continuum/test_godunov_sonic.cpp).
// Returns x, v = m / rho (0 in vacuum), rho at t_end and stats["steps"].
// Errors as solve_godunov.
ContinuumResult solve_pressureless(const InitialField& f, const ContinuumParams& p, double t_end,
                                   const ProgressCallback& progress = {});

// Its registration (registry.hpp).
SolverInfo pressureless_solver();

}  // namespace shockgas::continuum
