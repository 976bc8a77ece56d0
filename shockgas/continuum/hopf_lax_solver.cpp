// solve_hopf_lax: the exact inviscid solution on a grid, from pointwise data
// (HopfLaxSolution, hopf_lax.cpp) or from point masses (hopf_lax_bodies.cpp), and
// its registration as the exact reference solver.
#include <algorithm>
#include <cmath>
#include <limits>

#include "shockgas/continuum/hopf_lax.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::continuum {

namespace {

constexpr const char* kName = "hopf_lax";  // as registered

ContinuumResult solve_field(const InitialField& f, std::size_t cells, double t, const HopfLaxOptions& o) {
  const HopfLaxSolution s(f, t, hopf_lax_samples(cells, o));
  const CellAverages a = s.cell_averages(cells);
  ContinuumResult r;
  r.v = a.v;
  r.rho = a.rho;
  r.shocks = s.shocks();
  r.method_note = "exact: Legendre transform of " + std::to_string(s.samples()) +
                  " samples of Psi0 per period, minimisers refined on v0 to rounding";
  r.stats = s.stats();
  return r;
}

void check_grid(const InitialField& f, std::size_t cells, double t) {
  require(cells >= 1, "continuum.cells", cells, ">= 1");
  require_in_range("t", t, 0.0, std::numeric_limits<double>::max());
  require_above("initial.domain", f.length, 0.0);
}

// The characteristics' feet y = x - t v0(y) are found in doubles: their
// rounding, eps |t v0|, must stay below 1e-3 of a cell, so max |v0| t / h <=
// 1e-3 / eps = 4.5e12 (found: |v0| ~ 1e20 gave v in [-3990, -3662] for a sine of
// mean 0, and 1e50 lost the mass).
constexpr double kMaxShiftInCells = 4.5e12;  // 1e-3 / eps, eps = 2.2e-16

void check_rounding(const InitialField& f, std::size_t cells, double t) {
  if (f.from_bodies() || t == 0) return;
  const CellAverages a = cell_averages(f, cells);
  double v_max = 0;
  for (const double v : a.v) v_max = std::max(v_max, std::abs(v));
  const double h = f.length / static_cast<double>(cells);
  if (!(v_max * t / h > kMaxShiftInCells)) return;
  throw InputError(
      "initial.v0", "max |v0| = " + to_text(v_max),
      "max |v0| t / h <= " + to_text(kMaxShiftInCells, 2) + " for hopf_lax (it is " +
          to_text(v_max * t / h, 2) +
          "): the feet of the characteristics, x - t v0, would round by more than 1e-3 of a cell");
}

}  // namespace

ContinuumResult solve_hopf_lax(const InitialField& f, std::size_t cells, double t,
                               const HopfLaxOptions& options) {
  check_grid(f, cells, t);
  check_rounding(f, cells, t);
  ContinuumResult r =
      f.from_bodies() ? hopf_lax_point_masses(f, cells, t) : solve_field(f, cells, t, options);
  r.solver = kName;
  r.t = t;
  r.length = f.length;
  r.x = cell_centres(f.length, cells);
  r.has_shocks = true;
  return r;
}

CellAverages exact_cell_averages(const InitialField& f, std::size_t cells, double t,
                                 const HopfLaxOptions& options) {
  check_grid(f, cells, t);
  if (f.from_bodies()) {
    const ContinuumResult r = hopf_lax_point_masses(f, cells, t);
    return {r.v, r.rho};
  }
  return HopfLaxSolution(f, t, hopf_lax_samples(cells, options)).cell_averages(cells);
}

SolverInfo hopf_lax_solver() {
  SolverInfo s;
  s.name = kName;
  s.summary = "the exact inviscid limit (Hopf-Lax / Legendre transform; for particle data the sticky hull)";
  s.label = s.name + " (exact)";
  s.colour = "black";
  s.bytes_per_cell = 620;  // peak resident memory at work, measured at 2e4-4e5 cells
  // the hull's clusters and their teeth, beside the bodies: peak resident memory
  // 95 and 98 MB more per 10^6 bodies than a cell solver's at 1e6 and 2e6 bodies,
  // 4096 cells, t = 1 (the bodies' own 24 bytes counted apart)
  s.bytes_per_body = 100;
  s.density = true;
  s.shocks = true;
  s.exact = true;
  s.direct_in_time = true;
  s.by_default = true;
  s.preflight = [](const InitialField& f, const ContinuumParams& p, double t_end) {
    check_grid(f, p.cells, t_end);
    check_rounding(f, p.cells, t_end);
  };
  s.run = [](const InitialField& f, const ContinuumParams& p, double t_end, const ProgressCallback&) {
    HopfLaxOptions o;
    o.multiple_of = f.pieces;  // piecewise-constant data: every jump a sample node, so exact
    return solve_hopf_lax(f, p.cells, t_end, o);
  };
  return s;
}

}  // namespace shockgas::continuum
