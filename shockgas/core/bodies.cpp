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
  while (count > 0) {
    if (v_.empty() && count >= kBlock) {  // a whole block where it lies: no copy
      take_block(v, m, kBlock);
      v += kBlock, m += kBlock, count -= kBlock;
      continue;
    }
    if (v_.empty()) v_.reserve(kBlock), m_.reserve(kBlock);
    const std::size_t take = std::min(count, kBlock - v_.size());
    v_.insert(v_.end(), v, v + take), m_.insert(m_.end(), m, m + take);
    v += take, m += take, count -= take;
    if (v_.size() == kBlock) take_block(v_.data(), m_.data(), kBlock), v_.clear(), m_.clear();
  }
}

void TemperatureSums::take_block(const double* v, const double* m, std::size_t n) {
  double mass = 0, momentum = 0;
  for (std::size_t i = 0; i < n; ++i) mass += m[i], momentum += m[i] * v[i];
  if (mass > 0) {
    const double mean = momentum / mass;
    double squares = 0;
    for (std::size_t i = 0; i < n; ++i) squares += m[i] * (v[i] - mean) * (v[i] - mean);
    const double total = mass_ + mass, d = mean - mean_;
    squares_ += squares + d * d * (mass_ * mass / total);
    mean_ += d * (mass / total);
    mass_ = total;
  }
}

double TemperatureSums::temperature() const {
  TemperatureSums all = *this;
  if (!all.v_.empty()) all.take_block(all.v_.data(), all.m_.data(), all.v_.size());
  return all.mass_ > 0 ? all.squares_ / all.mass_ : 0.0;
}

}  // namespace shockgas
