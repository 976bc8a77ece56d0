#include "shockgas/continuum/solve.hpp"

#include <chrono>
#include <cmath>

#include "shockgas/continuum/godunov.hpp"
#include "shockgas/continuum/hopf_cole.hpp"
#include "shockgas/continuum/hopf_lax.hpp"
#include "shockgas/continuum/pressureless.hpp"
#include "shockgas/continuum/viscous_mol.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::continuum {

namespace {

ContinuumResult dispatch(const std::string& name, const InitialField& f, const ContinuumParams& p, double t_end,
                         const ProgressCallback& progress) {
  if (name == "godunov") return solve_godunov(f, p, t_end, 1, progress);
  if (name == "godunov2") return solve_godunov(f, p, t_end, 2, progress);
  if (name == "pressureless") return solve_pressureless(f, p, t_end, progress);
  if (name == "hopf_lax") return solve_hopf_lax(f, p.cells, t_end);
  if (name == "hopf_cole") return solve_hopf_cole(f, p, t_end, progress);
  if (name == "cvode") return solve_cvode(f, p, t_end, progress);
  if (name == "arkode") return solve_arkode(f, p, t_end, progress);
  throw InputError("continuum.solvers", to_text(name),
                   "\"godunov\", \"godunov2\", \"pressureless\", \"hopf_lax\", \"hopf_cole\", \"cvode\", \"arkode\"");
}

// A field with a non-finite value is a failure, never a result.
void require_finite(const ContinuumResult& r) {
  for (std::size_t i = 0; i < r.v.size(); ++i) {
    if (!std::isfinite(r.v[i]) || (i < r.rho.size() && !std::isfinite(r.rho[i])))
      throw RunError(r.solver + ": non-finite value at t = " + to_text(r.t) + " in cell " + std::to_string(i) +
                     " (x = " + to_text(r.x[i]) + ")");
  }
}

}  // namespace

ContinuumResult solve(const std::string& name, const InitialField& f, const ContinuumParams& p, double t_end,
                      const ProgressCallback& progress) {
  const auto start = std::chrono::steady_clock::now();
  ContinuumResult r = dispatch(name, f, p, t_end, progress);
  r.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (r.solver.empty()) r.solver = name;
  require_finite(r);
  return r;
}

}  // namespace shockgas::continuum
