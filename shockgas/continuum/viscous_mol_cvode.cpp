// solve_cvode: viscous Burgers + continuity by CVODE BDF, Newton-Krylov (SPGMR)
// with a banded preconditioner (CVBandPre). See viscous_mol.hpp.
#include <cvode/cvode_bandpre.h>
#include <cvode/cvode_ls.h>

#include "shockgas/continuum/sundials_wrap.hpp"
#include "shockgas/continuum/viscous_mol.hpp"
#include "shockgas/continuum/viscous_mol_setup.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::continuum {

namespace {

constexpr const char* kName = "cvode";  // as registered
constexpr long kHalfBandwidth = 5;      // interleaved (v, rho), 5-point stencils
constexpr int kKrylovDimension = 30;    // SPGMR restart length
constexpr long kMaxStepsPerOutput = 200000;

int rhs(double /*t*/, N_Vector y, N_Vector ydot, void* data) {
  const auto* grid = static_cast<const ViscousBurgersGrid*>(data);
  const std::size_t n = 2 * grid->cells;
  viscous_burgers_rhs(*grid, {N_VGetArrayPointer(y), n}, {N_VGetArrayPointer(ydot), n});
  return 0;
}

long counter(const sundials::Cvode& cv, int (*get)(void*, long*), const char* call) {
  long value = 0;
  cv.check(get(cv.get(), &value), call);
  return value;
}

void add_stats(const sundials::Cvode& cv, ContinuumResult& r) {
  r.stats["steps"] = static_cast<double>(counter(cv, CVodeGetNumSteps, "CVodeGetNumSteps"));
  r.stats["rhs_evaluations"] = static_cast<double>(counter(cv, CVodeGetNumRhsEvals, "CVodeGetNumRhsEvals"));
  r.stats["nonlinear_iterations"] =
      static_cast<double>(counter(cv, CVodeGetNumNonlinSolvIters, "CVodeGetNumNonlinSolvIters"));
  r.stats["linear_iterations"] = static_cast<double>(counter(cv, CVodeGetNumLinIters, "CVodeGetNumLinIters"));
  r.stats["error_test_failures"] =
      static_cast<double>(counter(cv, CVodeGetNumErrTestFails, "CVodeGetNumErrTestFails"));
  r.stats["preconditioner_setups"] =
      static_cast<double>(counter(cv, CVodeGetNumPrecEvals, "CVodeGetNumPrecEvals"));
}

}  // namespace

ContinuumResult solve_cvode(const InitialField& f, const ContinuumParams& p, double t_end,
                            const ProgressCallback& progress) {
  MolProblem m = make_mol_problem(f, p, t_end, kName);
  const std::size_t n = m.y0.size();
  sundials::Context ctx;
  sundials::Vector y(n, ctx);
  std::copy(m.y0.begin(), m.y0.end(), y.data().begin());
  if (t_end == 0) {
    ContinuumResult r = mol_result(m, y.data());
    r.method_note = "CVODE at t = 0: the initial cell averages";
    return r;
  }
  // The linear solver outlives the integrator that uses it (freed after CVodeFree).
  auto ls = sundials::LinearSolver::spgmr(y, SUN_PREC_LEFT, kKrylovDimension, ctx);
  sundials::Cvode cv(CV_BDF, ctx);
  cv.check(CVodeInit(cv.get(), rhs, 0.0, y), "CVodeInit");
  cv.check(CVodeSetUserData(cv.get(), &m.grid), "CVodeSetUserData");
  cv.check(CVodeSStolerances(cv.get(), m.rtol, m.atol), "CVodeSStolerances");
  cv.check(CVodeSetMaxNumSteps(cv.get(), kMaxStepsPerOutput), "CVodeSetMaxNumSteps");
  cv.check(CVodeSetStopTime(cv.get(), t_end), "CVodeSetStopTime");
  cv.check(CVodeSetLinearSolver(cv.get(), ls, nullptr), "CVodeSetLinearSolver");
  const auto bands = static_cast<sunindextype>(kHalfBandwidth);
  cv.check(CVBandPrecInit(cv.get(), static_cast<sunindextype>(n), bands, bands), "CVBandPrecInit");
  double t = 0;
  for (int k = 1; k <= kMolOutputs; ++k) {
    const double tout = t_end * k / kMolOutputs;
    cv.check(CVode(cv.get(), tout, y, &t, CV_NORMAL), "CVode");
    require_finite_state(m, y.data(), t);
    if (progress) progress(static_cast<double>(k) / kMolOutputs, t);
  }
  ContinuumResult r = mol_result(m, y.data());
  add_stats(cv, r);
  r.method_note =
      "CVODE BDF, Newton-Krylov SPGMR with banded preconditioner (CVBandPre, half-bandwidth 5); "
      "4th-order central flux for v, upwind mass flux; rtol = " +
      to_text(m.rtol) + ", atol = " + to_text(m.atol);
  return r;
}

SolverInfo cvode_solver() {
  SolverInfo s = mol_registration(kName);
  s.summary = "viscous Burgers + continuity, method of lines, CVODE (BDF, Newton-Krylov)";
  s.label = s.name + " (viscous, BDF)";
  s.colour = "tab:purple";
  s.bytes_per_cell = 700;  // peak resident memory at work, measured at 2e4-4e5 cells
  s.run = solve_cvode;
  return s;
}

}  // namespace shockgas::continuum
