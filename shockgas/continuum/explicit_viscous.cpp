// Explicit viscous Burgers (forward Euler, Godunov flux plus central diffusion):
// the reference for the diffusive step limit, see explicit_viscous.hpp.
#include "shockgas/continuum/explicit_viscous.hpp"

#include <algorithm>
#include <cmath>

#include "shockgas/continuum/burgers_physics.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::continuum {

namespace {

// Godunov flux of Burgers at an interface: f of the exact Riemann solution at xi = 0.
double godunov_flux(double vL, double vR) { return burgers_flux(burgers_riemann(vL, vR, 0.0).v); }

double max_abs(const std::vector<double>& v) {
  double m = 0;
  for (double x : v) m = std::max(m, std::abs(x));
  return m;
}

bool finite(const std::vector<double>& v) {
  return std::all_of(v.begin(), v.end(), [](double x) { return std::isfinite(x); });
}

// One forward-Euler step; next is overwritten with the new values.
void step(const std::vector<double>& v, std::vector<double>& next, double lambda, double mu) {
  const std::size_t n = v.size();
  for (std::size_t i = 0; i < n; ++i) {
    const double left = v[(i + n - 1) % n], right = v[(i + 1) % n];
    const double flux_difference = godunov_flux(v[i], right) - godunov_flux(left, v[i]);
    next[i] = v[i] - lambda * flux_difference + mu * (right - 2 * v[i] + left);
  }
}

}  // namespace

double periodic_total_variation(const std::vector<double>& v) {
  double tv = 0;
  for (std::size_t i = 0; i < v.size(); ++i) tv += std::abs(v[(i + 1) % v.size()] - v[i]);
  return tv;
}

double explicit_viscous_dt_limit(double max_speed, double h, double nu) {
  return 1.0 / (max_speed / h + 2.0 * nu / (h * h));
}

ExplicitViscousResult explicit_viscous_burgers(const std::vector<double>& v0, double h,
                                               const ExplicitViscousParams& p) {
  require(v0.size() >= 3, "explicit.cells", v0.size(), "at least 3 cells");
  require_above("explicit.h", h, 0.0);
  require_above("explicit.nu", p.nu, 0.0);
  require_above("explicit.dt", p.dt, 0.0);
  require(p.steps >= 1, "explicit.steps", p.steps, "at least 1 step");
  require_above("explicit.blow_up_factor", p.blow_up_factor, 1.0);

  const double bound = p.blow_up_factor * std::max(max_abs(v0), 1e-300);
  const double lambda = p.dt / h, mu = p.nu * p.dt / (h * h);
  ExplicitViscousResult r;
  r.v = v0;
  std::vector<double> next(v0.size());
  for (; r.steps < p.steps; ++r.steps) {
    step(r.v, next, lambda, mu);
    r.v.swap(next);
    const double m = max_abs(r.v);
    if (!(m <= bound) || !finite(r.v)) {  // NaN compares false: also a blow-up
      r.blew_up = true;
      ++r.steps;
      break;
    }
  }
  r.max_abs_v = max_abs(r.v);
  r.total_variation = periodic_total_variation(r.v);
  return r;
}

}  // namespace shockgas::continuum
