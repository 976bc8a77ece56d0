// solve_arkode: viscous Burgers + continuity by ARKODE's ARKStep IMEX: advection
// (of v and rho) explicit, diffusion implicit and linear, SPGMR with a banded
// preconditioner (ARKBandPre). See viscous_mol.hpp.
#include "shockgas/continuum/sundials_wrap.hpp"
#include "shockgas/continuum/viscous_mol.hpp"
#include "shockgas/continuum/viscous_mol_march.hpp"
#include "shockgas/continuum/viscous_mol_setup.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::continuum {

namespace {

constexpr const char* kName = "arkode";  // as registered
constexpr long kHalfBandwidth = 4;       // implicit part: v_i couples to v_{i+-2}, interleaved

}  // namespace

ContinuumResult solve_arkode(const InitialField& f, const ContinuumParams& p, double t_end,
                             const ProgressCallback& progress) {
  const MolProblem m = make_mol_problem(f, p, t_end, kName);
  if (t_end == 0) return mol_initial_result(m, "ARKODE");
  const auto advection = [&m](std::span<const double> y, std::span<double> ydot) {
    viscous_advection_rhs(m.grid, y, ydot);
  };
  const auto diffusion = [&m](std::span<const double> y, std::span<double> ydot) {
    viscous_diffusion_rhs(m.grid, y, ydot);
  };
  sundials::Arkode arkode(m.y0, advection, diffusion, mol_integrator_options(m, kHalfBandwidth));
  arkode.set_implicit_part_linear();
  ContinuumResult r = march_mol(m, arkode, progress);
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
