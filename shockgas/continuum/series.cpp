// solve_at_times: a registered solver's fields at several output times (series.hpp).
#include "shockgas/continuum/series.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

#include "shockgas/continuum/registry.hpp"
#include "shockgas/continuum/solve.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::continuum {

namespace {

void check_times(const std::vector<double>& times) {
  for (std::size_t k = 0; k < times.size(); ++k) {
    require(std::isfinite(times[k]) && times[k] >= 0, "times", times[k], "output times >= 0");
    if (k > 0) require(times[k] >= times[k - 1], "times", times[k], "output times in increasing order");
  }
}

// The fields at t = 0: the cell averages of the initial data.
ContinuumResult initial_fields(const SolverInfo& info, const InitialField& f, const ContinuumParams& p) {
  const CellAverages a = cell_averages(f, p.cells);
  ContinuumResult r;
  r.solver = info.name;
  r.length = f.length;
  r.x = cell_centres(f.length, p.cells);
  r.v = a.v;
  if (info.density) r.rho = a.rho;
  r.has_shocks = info.shocks;
  r.method_note = "t = 0: the cell averages of the initial data";
  return r;
}

// progress of step k of n, mapped into the whole series.
ProgressCallback step_progress(const ProgressCallback& progress, std::size_t k, std::size_t n) {
  if (!progress) return {};
  return [progress, k, n](double fraction, double t, std::uint64_t events) {
    progress((static_cast<double>(k) + fraction) / static_cast<double>(n), t, events);
  };
}

}  // namespace

InitialField piecewise_constant_field(const ContinuumResult& r) {
  require(!r.v.empty(), "continuum.cells", r.v.size(), ">= 1");
  auto state = std::make_shared<const ContinuumResult>(r);
  auto cell = [state](double x) {
    const auto n = static_cast<double>(state->v.size());
    const double i = std::floor(x / state->length * n);
    return static_cast<std::size_t>(std::clamp(i, 0.0, n - 1));
  };
  InitialField f;
  f.length = r.length;
  f.v0 = [state, cell](double x) { return state->v[cell(x)]; };
  f.rho0 = [state, cell](double x) { return state->rho.empty() ? 1.0 : state->rho[cell(x)]; };
  return f;
}

std::vector<ContinuumResult> solve_at_times(const std::string& name, const InitialField& f,
                                            const ContinuumParams& p, const std::vector<double>& times,
                                            const ProgressCallback& progress) {
  const SolverInfo& info = solver_info(name);
  check_boundary(info, p);
  check_times(times);
  std::vector<ContinuumResult> out;
  out.reserve(times.size());
  std::unique_ptr<ContinuumResult> last;  // the latest marched state
  for (std::size_t k = 0; k < times.size(); ++k) {
    const double t = times[k];
    ContinuumResult r;
    if (t == 0) {
      r = initial_fields(info, f, p);
    } else if (info.direct_in_time || !last) {
      r = solve(name, f, p, t, step_progress(progress, k, times.size()));
    } else if (t == last->t) {
      r = *last;
    } else {
      r = solve(name, piecewise_constant_field(*last), p, t - last->t,
                step_progress(progress, k, times.size()));
      r.t = t;
    }
    if (t > 0 && !info.direct_in_time) last = std::make_unique<ContinuumResult>(r);
    out.push_back(std::move(r));
  }
  if (progress) progress(1.0, times.empty() ? 0.0 : times.back(), 0);
  return out;
}

}  // namespace shockgas::continuum
