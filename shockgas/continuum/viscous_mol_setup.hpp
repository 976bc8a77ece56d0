#pragma once
// What solve_cvode and solve_arkode share: input checks, the initial state, the
// tolerances, the finiteness check and the result. Private to shockgas_continuum.
#include <span>
#include <string>
#include <vector>

#include "shockgas/continuum/viscous_mol.hpp"

namespace shockgas::continuum {

struct MolProblem {
  std::string solver;  // the registered name, for messages and the result
  ViscousBurgersGrid grid;
  std::vector<double> y0;       // interleaved (v_i, rho_i) cell averages at t = 0
  double rtol = 0, atol = 0;    // atol = rtol * max(max|v0|, max rho0)
  double v_min = 0, v_max = 0;  // the range of v0's cell averages (maximum principle)
  bool bounded = true;          // v held to that range (not under continuum.allow_unstable)
  double t_end = 0;
  double length = 1;
};

// Checks the input (InputError naming the key) and builds the problem.
MolProblem make_mol_problem(const InitialField& f, const ContinuumParams& p, double t_end,
                            const std::string& solver);

// The input checks of make_mol_problem alone (the solvers' preflight).
void check_mol_input(const InitialField& f, const ContinuumParams& p, double t_end);

// What the registrations of cvode and arkode share: the flags, the preflight.
SolverInfo mol_registration(const std::string& name);

// Output times of the integration (progress is reported at each): t_end * k / kOutputs.
constexpr int kMolOutputs = 10;

// RunError naming the solver, the cell, its centre and the time if y has a
// non-finite entry, or a velocity outside the range of the initial ones by more
// than max(1e-2, 10 rtol) of that range. Viscous Burgers keeps v in [min v0,
// max v0] (maximum principle), and so does the central semi-discretization at
// cell Peclet number Dv h / nu <= 2, which the preflight requires; a state far
// outside it is an integration that failed without saying so (found: cvode at
// nu = 1e8 returned |v| = 10 from |v0| <= 1). Not under allow_unstable, which
// runs at cell Peclet numbers above 2, where central differences overshoot.
void require_finite_state(const MolProblem& m, std::span<const double> y, double t);

// The stiffness nu t_end / h^2 up to which the integrators are measured to
// hold their accuracy: on a sine wave of 64 cells to t = 0.1, cvode's global
// error stays below 1e-3 of the velocity range up to 4e7 and is 0.15 of it at
// 4e8 (arkode stops with an error-test failure beyond about 4e5).
constexpr double kMaxMolStiffness = 4e7;

// The result at t_end from the final state; the caller adds stats and the note.
ContinuumResult mol_result(const MolProblem& m, std::span<const double> y);

// The result at t_end = 0 (no integration): the initial cell averages, so noted for the integrator.
ContinuumResult mol_initial_result(const MolProblem& m, const std::string& integrator);

}  // namespace shockgas::continuum
