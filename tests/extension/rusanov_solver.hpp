#pragma once
// A continuum solver written outside shockgas, as docs/design.md §5 ("A solver")
// shows: Burgers' velocity by the first-order Rusanov (local
// Lax-Friedrichs) flux on the periodic grid,
//
//     F_{i+1/2} = (f(v_i) + f(v_{i+1})) / 2 - a (v_{i+1} - v_i) / 2,   a = max(|v_i|, |v_{i+1}|),
//
// f = v^2 / 2, dt = cfl dx / max|v| (monotone for cfl <= 1; LeVeque 2002, §12.5).
#include <algorithm>
#include <cmath>

#include "shockgas/continuum/registry.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::extension {

// Its own limits: a periodic grid only (the flux wraps), a monotone Courant number.
inline void check_rusanov(const InitialField&, const continuum::ContinuumParams& p, double t_end) {
  require(p.cfl <= 1 || p.allow_unstable, "continuum.cfl", p.cfl, "a Courant number in (0, 1] for rusanov");
  require(std::isfinite(t_end) && t_end >= 0, "continuum.t_end", t_end, "a finite time >= 0");
}

inline continuum::ContinuumResult solve_rusanov(const InitialField& f, const continuum::ContinuumParams& p,
                                                double t_end, const ProgressCallback&) {
  check_rusanov(f, p, t_end);
  const std::size_t n = p.cells;
  const double dx = f.length / static_cast<double>(n);
  std::vector<double> v = continuum::cell_averages(f, n).v, flux(n);
  for (double t = 0; t < t_end;) {
    const double vmax = std::max(
        1e-300, std::abs(*std::max_element(v.begin(), v.end(),
                                           [](double a, double b) { return std::abs(a) < std::abs(b); })));
    const double dt = std::min(p.cfl * dx / vmax, t_end - t);
    for (std::size_t i = 0; i < n; ++i) {
      const double l = v[i], r = v[(i + 1) % n];
      flux[i] = 0.25 * (l * l + r * r) - 0.5 * std::max(std::abs(l), std::abs(r)) * (r - l);
    }
    for (std::size_t i = 0; i < n; ++i) v[i] -= dt / dx * (flux[i] - flux[(i + n - 1) % n]);
    t = dt < t_end - t ? t + dt : t_end;
  }
  continuum::ContinuumResult r;
  r.t = t_end;
  r.length = f.length;
  r.x = continuum::cell_centres(f.length, n);
  r.v = v;
  r.method_note = "first-order Rusanov flux (a solver registered by a test)";
  return r;
}

inline continuum::SolverInfo rusanov_solver() {
  continuum::SolverInfo s;
  s.name = "rusanov";
  s.summary = "Burgers' velocity, first-order Rusanov flux";
  s.label = "rusanov (1st order)";
  s.colour = "tab:olive";
  s.preflight = check_rusanov;
  s.run = solve_rusanov;
  return s;
}

}  // namespace shockgas::extension
