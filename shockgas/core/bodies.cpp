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
    if (v_.empty() && count >= kBlock) {  // whole blocks where they lie: no copy
      const std::size_t blocks = count / kBlock;
      take_blocks(v, m, blocks);
      v += blocks * kBlock, m += blocks * kBlock, count -= blocks * kBlock;
      continue;
    }
    if (v_.empty()) v_.reserve(kBlock), m_.reserve(kBlock);
    const std::size_t take = std::min(count, kBlock - v_.size());
    v_.insert(v_.end(), v, v + take), m_.insert(m_.end(), m, m + take);
    v += take, m += take, count -= take;
    if (v_.size() == kBlock) take_blocks(v_.data(), m_.data(), 1), v_.clear(), m_.clear();
  }
}

// A block's first pass: M_b, P_b and its mean; the energy's sum runs on from
// the earlier blocks' (one sum in the bodies' order).
TemperatureSums::FirstPass TemperatureSums::first_pass(const double* v, const double* m, std::size_t n) {
  double mass = 0, momentum = 0, energy = energy_;
  for (std::size_t i = 0; i < n; ++i)
    mass += m[i], momentum += m[i] * v[i], energy += 0.5 * m[i] * v[i] * v[i];
  energy_ = energy;
  return {mass, mass > 0 ? momentum / mass : 0.0};
}

// C_b = sum m (v - mean_b)^2 of a block.
double TemperatureSums::second_pass(const double* v, const double* m, std::size_t n, double mean) {
  double squares = 0;
  for (std::size_t i = 0; i < n; ++i) squares += m[i] * (v[i] - mean) * (v[i] - mean);
  return squares;
}

// A block's sums folded into the totals (a block without mass is left out).
void TemperatureSums::combine(FirstPass b, double squares) {
  if (!(b.mass > 0)) return;
  const double total = mass_ + b.mass, d = b.mean - mean_;
  squares_ += squares + d * d * (mass_ * b.mass / total);
  mean_ += d * (b.mass / total);
  mass_ = total;
}

// Blocks in a row: block k's second pass runs beside block k + 1's first (the
// loop below is second_pass and first_pass in one), the sums of each block and
// their order as one block at a time (the same bits; each pass alone is one
// chain of dependent additions, two overlap).
void TemperatureSums::take_blocks(const double* v, const double* m, std::size_t blocks) {
  FirstPass previous = first_pass(v, m, kBlock);
  for (std::size_t k = 1; k < blocks; ++k, v += kBlock, m += kBlock) {
    const double* nv = v + kBlock;
    const double* nm = m + kBlock;
    const double mean = previous.mean;
    double squares = 0, mass = 0, momentum = 0, energy = energy_;
    for (std::size_t i = 0; i < kBlock; ++i) {
      squares += m[i] * (v[i] - mean) * (v[i] - mean);
      mass += nm[i], momentum += nm[i] * nv[i], energy += 0.5 * nm[i] * nv[i] * nv[i];
    }
    energy_ = energy;
    combine(previous, squares);
    previous = {mass, mass > 0 ? momentum / mass : 0.0};
  }
  combine(previous, second_pass(v, m, kBlock, previous.mean));
}

double TemperatureSums::kinetic_energy() const {
  double energy = energy_;
  for (std::size_t i = 0; i < v_.size(); ++i) energy += 0.5 * m_[i] * v_[i] * v_[i];
  return energy;
}

double TemperatureSums::temperature() const {
  TemperatureSums all = *this;
  if (!all.v_.empty()) {  // the block being filled, as it stands
    const FirstPass b = all.first_pass(all.v_.data(), all.m_.data(), all.v_.size());
    all.combine(b, second_pass(all.v_.data(), all.m_.data(), all.v_.size(), b.mean));
  }
  return all.mass_ > 0 ? all.squares_ / all.mass_ : 0.0;
}

}  // namespace shockgas
