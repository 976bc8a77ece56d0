#include "shockgas/compare/scaling_laws.hpp"

#include <cmath>
#include <limits>

#include "shockgas/core/error.hpp"

namespace shockgas::compare {

double inelasticity(double r) {
  require_in_range("particles.r", r, 0.0, 1.0);
  return 0.5 * (1.0 - r);
}

double dissipation_time(double r) {
  const double eps = inelasticity(r);
  return eps > 0 ? 1.0 / eps : std::numeric_limits<double>::infinity();
}

double sticking_time(double r) {
  const double eps = inelasticity(r);
  return eps > 0 ? std::pow(eps, -1.5) : std::numeric_limits<double>::infinity();
}

double expected_shock_count(double N, double t) {
  require_above("compare.N", N, 0.0);
  require_above("compare.t", t, 0.0);
  return N * std::pow(t, -2.0 / 3.0);
}

double shock_count_ratio(std::size_t n_shocks, double N, double t) {
  return static_cast<double>(n_shocks) / expected_shock_count(N, t);
}

double scaled_velocity(double v, double t) { return v * std::cbrt(t); }

}  // namespace shockgas::compare
