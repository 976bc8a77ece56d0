#include "shockgas/core/bodies.hpp"

#include <algorithm>
#include <cmath>

#include "shockgas/core/error.hpp"

namespace shockgas {

void require_finite_body(BodiesView b, std::size_t i, const std::string& key) {
  if (std::isfinite(b.x[i]) && std::isfinite(b.v[i]) && std::isfinite(b.m[i]) && b.m[i] > 0) return;
  const std::string at = "[" + std::to_string(i) + "]";
  require(std::isfinite(b.x[i]), key + ".x" + at, b.x[i], "a finite position");
  require(std::isfinite(b.v[i]), key + ".v" + at, b.v[i], "a finite velocity");
  require(false, key + ".m" + at, b.m[i], "a finite mass > 0");
}

void require_finite_bodies(BodiesView b, const std::string& key) {
  for (std::size_t i = 0; i < b.size(); ++i) require_finite_body(b, i, key);
}

double total_mass(const Bodies& b) {
  double s = 0;
  for (double mi : b.m) s += mi;
  return s;
}

double total_momentum(const Bodies& b) {
  double s = 0;
  for (std::size_t i = 0; i < b.size(); ++i) s += b.m[i] * b.v[i];
  return s;
}

double kinetic_energy(const Bodies& b) {
  double s = 0;
  for (std::size_t i = 0; i < b.size(); ++i) s += 0.5 * b.m[i] * b.v[i] * b.v[i];
  return s;
}

double temperature(const Bodies& b) {
  const double m = total_mass(b);
  if (m <= 0) return 0;
  const double mean = total_momentum(b) / m;
  double s = 0;
  for (std::size_t i = 0; i < b.size(); ++i) {
    const double dv = b.v[i] - mean;
    s += b.m[i] * dv * dv;
  }
  return s / m;
}

void TemperatureSums::add(const double* v, const double* m, std::size_t count) {
  if (count == 0) return;
  if (!shifted_) shift_ = v[0], shifted_ = true;
  for (std::size_t i = 0; i < count; ++i) {
    const double dv = v[i] - shift_;
    mass_ += m[i];
    first_ += m[i] * dv;
    second_ += m[i] * dv * dv;
  }
}

double TemperatureSums::temperature() const {
  if (mass_ <= 0) return 0;
  const double mean = first_ / mass_;
  return std::max(0.0, second_ / mass_ - mean * mean);
}

}  // namespace shockgas
