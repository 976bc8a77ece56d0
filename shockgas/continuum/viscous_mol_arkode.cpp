// solve_arkode: viscous Burgers + continuity by ARKODE's ARKStep IMEX: advection
// (of v and rho) explicit, diffusion implicit and linear, SPGMR with a banded
// preconditioner (ARKBandPre). See viscous_mol.hpp.
#include <arkode/arkode_bandpre.h>

#include "shockgas/continuum/sundials_wrap.hpp"
#include "shockgas/continuum/viscous_mol.hpp"
#include "shockgas/continuum/viscous_mol_setup.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::continuum {

namespace {

constexpr const char* kName = "arkode";  // as registered
constexpr long kHalfBandwidth = 4;       // implicit part: v_i couples to v_{i+-2}, interleaved
constexpr int kKrylovDimension = 30;     // SPGMR restart length
constexpr long kMaxStepsPerOutput = 200000;

std::span<double> view(N_Vector v, std::size_t n) { return {N_VGetArrayPointer(v), n}; }

int explicit_rhs(double /*t*/, N_Vector y, N_Vector ydot, void* data) {
  const auto* grid = static_cast<const ViscousBurgersGrid*>(data);
  viscous_advection_rhs(*grid, view(y, 2 * grid->cells), view(ydot, 2 * grid->cells));
  return 0;
}

int implicit_rhs(double /*t*/, N_Vector y, N_Vector ydot, void* data) {
  const auto* grid = static_cast<const ViscousBurgersGrid*>(data);
  viscous_diffusion_rhs(*grid, view(y, 2 * grid->cells), view(ydot, 2 * grid->cells));
  return 0;
}

long counter(const sundials::Arkode& ark, int (*get)(void*, long*), const char* call) {
  long value = 0;
  ark.check(get(ark.get(), &value), call);
  return value;
}

void add_stats(const sundials::Arkode& ark, ContinuumResult& r) {
  long fe = 0, fi = 0;
  ark.check(ARKStepGetNumRhsEvals(ark.get(), &fe, &fi), "ARKStepGetNumRhsEvals");
  r.stats["rhs_explicit"] = static_cast<double>(fe);
  r.stats["rhs_implicit"] = static_cast<double>(fi);
  r.stats["steps"] = static_cast<double>(counter(ark, ARKStepGetNumSteps, "ARKStepGetNumSteps"));
  r.stats["step_attempts"] =
      static_cast<double>(counter(ark, ARKStepGetNumStepAttempts, "ARKStepGetNumStepAttempts"));
  r.stats["nonlinear_iterations"] =
      static_cast<double>(counter(ark, ARKStepGetNumNonlinSolvIters, "ARKStepGetNumNonlinSolvIters"));
  r.stats["linear_iterations"] =
      static_cast<double>(counter(ark, ARKStepGetNumLinIters, "ARKStepGetNumLinIters"));
  r.stats["error_test_failures"] =
      static_cast<double>(counter(ark, ARKStepGetNumErrTestFails, "ARKStepGetNumErrTestFails"));
  r.stats["preconditioner_setups"] =
      static_cast<double>(counter(ark, ARKStepGetNumPrecEvals, "ARKStepGetNumPrecEvals"));
}

}  // namespace

ContinuumResult solve_arkode(const InitialField& f, const ContinuumParams& p, double t_end,
                             const ProgressCallback& progress) {
  MolProblem m = make_mol_problem(f, p, t_end, kName);
  const std::size_t n = m.y0.size();
  sundials::Context ctx;
  sundials::Vector y(n, ctx);
  std::copy(m.y0.begin(), m.y0.end(), y.data().begin());
  if (t_end == 0) {
    ContinuumResult r = mol_result(m, y.data());
    r.method_note = "ARKODE at t = 0: the initial cell averages";
    return r;
  }
  // The linear solver outlives the integrator that uses it (freed after ARKStepFree).
  auto ls = sundials::LinearSolver::spgmr(y, SUN_PREC_LEFT, kKrylovDimension, ctx);
  sundials::Arkode ark(explicit_rhs, implicit_rhs, 0.0, y, ctx);
  ark.check(ARKStepSetUserData(ark.get(), &m.grid), "ARKStepSetUserData");
  ark.check(ARKStepSStolerances(ark.get(), m.rtol, m.atol), "ARKStepSStolerances");
  ark.check(ARKStepSetMaxNumSteps(ark.get(), kMaxStepsPerOutput), "ARKStepSetMaxNumSteps");
  ark.check(ARKStepSetStopTime(ark.get(), t_end), "ARKStepSetStopTime");
  ark.check(ARKStepSetLinearSolver(ark.get(), ls, nullptr), "ARKStepSetLinearSolver");
  ark.check(ARKStepSetLinear(ark.get(), 0), "ARKStepSetLinear");  // fi linear, time-independent
  const auto bands = static_cast<sunindextype>(kHalfBandwidth);
  ark.check(ARKBandPrecInit(ark.get(), static_cast<sunindextype>(n), bands, bands), "ARKBandPrecInit");
  double t = 0;
  for (int k = 1; k <= kMolOutputs; ++k) {
    const double tout = t_end * k / kMolOutputs;
    ark.check(ARKStepEvolve(ark.get(), tout, y, &t, ARK_NORMAL), "ARKStepEvolve");
    require_finite_state(m, y.data(), t);
    if (progress) progress(static_cast<double>(k) / kMolOutputs, t);
  }
  ContinuumResult r = mol_result(m, y.data());
  add_stats(ark, r);
  r.method_note =
      "ARKODE ARKStep IMEX (ARK 4(3)): explicit advection (4th-order central flux for v, upwind "
      "mass flux), implicit linear diffusion, SPGMR with banded preconditioner (ARKBandPre); "
      "rtol = " +
      to_text(m.rtol) + ", atol = " + to_text(m.atol);
  return r;
}

SolverInfo arkode_solver() {
  SolverInfo s = mol_registration(kName);
  s.summary = "viscous Burgers + continuity, method of lines, ARKODE (IMEX additive Runge-Kutta)";
  s.label = s.name + " (viscous, IMEX)";
  s.colour = "tab:brown";
  s.bytes_per_cell = 850;  // peak resident memory at work, measured at 2e4-4e5 cells
  s.run = solve_arkode;
  return s;
}

}  // namespace shockgas::continuum
