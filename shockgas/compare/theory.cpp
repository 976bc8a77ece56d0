#include "shockgas/compare/theory.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

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

double homogeneous_cooling_temperature(double r, double t) {
  const double a = 1.0 + inelasticity(r) * t;
  return 1.0 / (a * a);
}

double sticky_gas_temperature(double t) { return std::pow(t, kStickyCoolingExponent); }

double typical_cluster_mass(double t) { return std::pow(t, 2.0 / 3.0); }

double expected_shock_count(double N, double t) {
  require_above("initial.N", N, 0.0);
  require_above("compare.t", t, 0.0);
  return N * std::pow(t, kStickyCoolingExponent);  // N t^(-2/3)
}

double shock_count_ratio(std::size_t n_shocks, double N, double t) {
  return static_cast<double>(n_shocks) / expected_shock_count(N, t);
}

double automatic_min_cluster_particles(double t) { return std::max(2.0, 0.1 * typical_cluster_mass(t)); }

double scaled_velocity(double v, double t) { return v * std::cbrt(t); }

double validity_time(double delta) {
  return delta > 0 ? std::pow(delta, -3.0) : std::numeric_limits<double>::infinity();
}

double breaking_time(const std::function<double(double)>& v0, double length) {
  require_above("initial.domain", length, 0.0);
  constexpr int kPoints = 1 << 16;
  const double h = length / kPoints;
  std::vector<double> v(kPoints);
  for (int i = 0; i < kPoints; ++i) v[i] = v0(i * h);
  const auto at = [&](int i) { return v[(i + kPoints) % kPoints]; };
  // max(-v0'), by differences centred on the midpoints
  int steepest = 0;
  for (int i = 1; i < kPoints; ++i)
    if (at(i) - at(i + 1) > at(steepest) - at(steepest + 1)) steepest = i;
  const double fine = (at(steepest) - at(steepest + 1)) / h;
  if (!(fine > 0)) return std::numeric_limits<double>::infinity();
  // A downward jump J there: the difference is J / h, and halves over the
  // two spacings around it (a smooth slope keeps its value); -v0' is
  // unbounded and the shock exists at t = 0.
  const double coarse =
      std::max(at(steepest - 1) - at(steepest + 1), at(steepest) - at(steepest + 2)) / (2 * h);
  return fine > 1.5 * coarse ? 0.0 : 1.0 / fine;
}

}  // namespace shockgas::compare
