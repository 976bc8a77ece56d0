#include "shockgas/continuum/solve.hpp"

#include <chrono>
#include <cmath>

#include "shockgas/continuum/registry.hpp"
#include "shockgas/core/error.hpp"
#include "shockgas/core/interrupt.hpp"

namespace shockgas::continuum {

namespace {

// A field with a non-finite value is a failure, never a result.
void require_finite(const ContinuumResult& r) {
  for (std::size_t i = 0; i < r.v.size(); ++i) {
    if (!std::isfinite(r.v[i]) || (i < r.rho.size() && !std::isfinite(r.rho[i])))
      throw RunError(r.solver + ": non-finite value at t = " + to_text(r.t) + " in cell " +
                     std::to_string(i) + " (x = " + to_text(r.x[i]) + ")");
  }
}

}  // namespace

ContinuumResult solve(const std::string& name, const InitialField& f, const ContinuumParams& p, double t_end,
                      const ProgressCallback& progress) {
  const SolverInfo& info = solver_info(name);
  check_boundary(info, p);
  const auto start = std::chrono::steady_clock::now();
  // The solvers' progress points are their safe points: an abort request stops them there.
  const ProgressCallback checked = [&progress](double fraction, double t, std::uint64_t events) {
    throw_if_aborted();
    if (progress) progress(fraction, t, events);
  };
  ContinuumResult r = info.run(f, p, t_end, checked);
  throw_if_aborted();
  r.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.solver = info.name;
  require_finite(r);
  return r;
}

}  // namespace shockgas::continuum
