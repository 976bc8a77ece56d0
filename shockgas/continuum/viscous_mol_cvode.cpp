// solve_cvode: viscous Burgers + continuity by CVODE BDF, Newton-Krylov (SPGMR)
// with a banded preconditioner (CVBandPre). See viscous_mol.hpp.
#include "shockgas/continuum/sundials_wrap.hpp"
#include "shockgas/continuum/viscous_mol.hpp"
#include "shockgas/continuum/viscous_mol_march.hpp"
#include "shockgas/continuum/viscous_mol_setup.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::continuum {

namespace {

constexpr const char* kName = "cvode";  // as registered
constexpr long kHalfBandwidth = 5;      // interleaved (v, rho), 5-point stencils

}  // namespace

ContinuumResult solve_cvode(const InitialField& f, const ContinuumParams& p, double t_end,
                            const ProgressCallback& progress) {
  const MolProblem m = make_mol_problem(f, p, t_end, kName);
  if (t_end == 0) return mol_initial_result(m, "CVODE");
  const auto rhs = [&m](std::span<const double> y, std::span<double> ydot) {
    viscous_burgers_rhs(m.grid, y, ydot);
  };
  sundials::Cvode cvode(CV_BDF, m.y0, rhs, mol_integrator_options(m, kHalfBandwidth));
  ContinuumResult r = march_mol(m, cvode, progress);
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
