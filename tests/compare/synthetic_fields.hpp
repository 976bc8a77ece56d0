#pragma once
// Exact synthetic fields for the comparison tests: the late-time sawtooth of the
// sticky gas / inviscid Burgers with uniform initial density, built from its
// Lagrangian description. Between shocks X_k < X_{k+1} the velocity is the ramp
//   v(x) = (x - q_k) / t        (all mass of [q_{k-1}, q_k] sits in shock k),
// so shock k has mass rho0 (q_k - q_{k-1}), jump (q_{k-1} - q_k) / t and the
// Burgers speed (v_L + v_R) / 2. The ring has length L; q_{-1} = q_{K-1} - L.
#include <cmath>
#include <cstddef>
#include <vector>

#include "shockgas/continuum/field.hpp"

namespace shockgas::compare::testing {

struct Sawtooth {
  double L = 100, t = 10;
  std::vector<double> X;  // shock positions, sorted, in [0, L)
  std::vector<double> q;  // q_k in (X_k, X_{k+1}) (the last one may exceed L)

  std::size_t previous(std::size_t k) const { return (k + X.size() - 1) % X.size(); }
  double q_before(std::size_t k) const { return k == 0 ? q.back() - L : q[k - 1]; }
  double mass(std::size_t k) const { return q[k] - q_before(k); }
  double jump(std::size_t k) const { return (q_before(k) - q[k]) / t; }
  double v_left(std::size_t k) const { return (X[k] - q_before(k)) / t; }
  double v_right(std::size_t k) const { return (X[k] - q[k]) / t; }
  double shock_speed(std::size_t k) const { return 0.5 * (v_left(k) + v_right(k)); }

  // The ramp index that covers x in [0, L).
  std::size_t ramp_at(double x) const {
    std::size_t k = X.size() - 1;  // before X_0: the last ramp, wrapped
    for (std::size_t i = 0; i < X.size(); ++i)
      if (X[i] <= x) k = i;
    return k;
  }
  double v(double x) const {
    const std::size_t k = ramp_at(x);
    const double unrolled = x < X[0] ? x + L : x;
    return (unrolled - q[k]) / t;
  }

  // Exact cell averages of v (piecewise-linear pieces integrated by their
  // midpoint value) and of rho (each shock's mass in its cell), on `cells` cells.
  continuum::ContinuumResult cell_averages(std::size_t cells) const {
    continuum::ContinuumResult r;
    r.solver = "synthetic";
    r.t = t;
    r.length = L;
    r.x = continuum::cell_centres(L, cells);
    r.v.assign(cells, 0.0);
    r.rho.assign(cells, 0.0);
    const double dx = L / static_cast<double>(cells);
    for (std::size_t c = 0; c < cells; ++c) {
      const double a = static_cast<double>(c) * dx, b = a + dx;
      std::vector<double> cuts{a};
      for (double s : X)
        if (s > a && s < b) cuts.push_back(s);
      cuts.push_back(b);
      double integral = 0;
      for (std::size_t p = 0; p + 1 < cuts.size(); ++p)
        integral += (cuts[p + 1] - cuts[p]) * v(0.5 * (cuts[p] + cuts[p + 1]));
      r.v[c] = integral / dx;
    }
    for (std::size_t k = 0; k < X.size(); ++k) {
      const std::size_t c = static_cast<std::size_t>(X[k] / dx);
      r.rho[c] += mass(k) / dx;
    }
    return r;
  }
};

// Five shocks on a ring of length 100 at t = 10, one in the last cell so that its
// compression region wraps across x = 0; masses 4.5, 25, 30, 20, 20.5.
inline Sawtooth five_shock_sawtooth() {
  Sawtooth s;
  s.L = 100;
  s.t = 10;
  s.X = {2.03, 13.21, 40.05, 71.777, 99.96};
  s.q = {5.0, 30.0, 60.0, 80.0, 100.5};
  return s;
}

}  // namespace shockgas::compare::testing
