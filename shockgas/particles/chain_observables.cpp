#include "shockgas/particles/chain_observables.hpp"

#include <cmath>

namespace shockgas::particles::detail {

ClusterCounter::ClusterCounter(double L, bool ring, const ClusterCriteria& criteria,
                               const MultiParticleRule& rule)
    : L_(L), ring_(ring), criteria_(criteria), rule_(rule), wrap_(L) {}

// The counter's state lives in locals through a chunk (stores to members would
// be repeated every body: the compiler cannot rule out that they alias the chunk).
void ClusterCounter::add(const ChainChunk& chunk) {
  if (chunk.size == 0) return;
  std::size_t k = 0;
  if (bodies_ == 0) {
    x0_ = last_x_ = ring_ ? wrap_(chunk.x[0]) : chunk.x[0];
    v0_ = last_v_ = chunk.v[0];
    lone_.start(!rule_.heavy(chunk.m[0]));
    k = 1;
  }
  const ClusterCriteria criteria = criteria_;
  const MultiParticleRule rule = rule_;
  double last_x = last_x_, last_v = last_v_;
  std::size_t joined = joined_;
  LoneBodies lone = lone_;
  for (; k < chunk.size; ++k) {
    const double w = ring_ ? wrap_(chunk.x[k]) : chunk.x[k];
    double gap = w - last_x;
    if (w < last_x) [[unlikely]] {
      if (ring_ && !seam_)
        seam_ = true, gap = w + L_ - last_x;  // the ring's wrapping pair
      else
        ordered_ = false;
    }
    const bool joins = criteria.joins(gap, chunk.v[k] - last_v);
    joined += joins;
    lone.add(joins, !rule.heavy(chunk.m[k]));
    last_x = w, last_v = chunk.v[k];
  }
  last_x_ = last_x, last_v_ = last_v, joined_ = joined, lone_ = lone;
  bodies_ += chunk.size;
}

std::optional<std::size_t> ClusterCounter::count() const {
  if (!ring_)
    return ordered_ ? std::optional(bodies_ - joined_ - lone_.with_cuts(false, false)) : std::nullopt;
  if (bodies_ < 2) return bodies_ - lone_.with_cuts(false, false);  // one body holds every particle
  // The pair (last, first) closes the ring: the wrapping pair if the positions
  // never dropped, else an ordinary pair that must be in order.
  const bool ordered = ordered_ && (!seam_ || x0_ >= last_x_);
  if (!ordered) return std::nullopt;
  const double gap = seam_ ? x0_ - last_x_ : x0_ + L_ - last_x_;
  const bool closing = criteria_.joins(gap, v0_ - last_v_);
  const std::size_t joined = joined_ + closing;
  const std::size_t clusters = joined < bodies_ ? bodies_ - joined : 1;  // a fully joined ring is one
  return clusters - lone_.with_cuts(closing, closing);
}

ChainMoments chain_moments(const ChainView& chain, ClusterCounter* counter) {
  ChainMoments s;
  chain.visit(
      [&](const ChainChunk& c) {
        double mass = s.mass, momentum = s.momentum;  // the same sums, in registers
        for (std::size_t k = 0; k < c.size; ++k) mass += c.m[k], momentum += c.m[k] * c.v[k];
        s.mass = mass, s.momentum = momentum;
        if (counter) counter->add(c);
      },
      counter ? Fields::all : Fields::velocities);  // positions only for the clusters
  return s;
}

double chain_temperature(const ChainView& chain, const ChainMoments& moments, const HistogramSpec& spec,
                         std::vector<double>* row) {
  const double mean = moments.mean();
  const double dz = 2 * spec.zmax / static_cast<double>(spec.bins);
  const double bins = static_cast<double>(spec.bins);
  const double density = moments.mass * dz;
  if (row) row->assign(spec.bins, 0.0);
  double T = 0;
  chain.visit(
      [&](const ChainChunk& c) {
        double sum = T;
        for (std::size_t k = 0; k < c.size; ++k) sum += c.m[k] * (c.v[k] - mean) * (c.v[k] - mean);
        T = sum;
        if (!row) return;
        // Bin floor(z): z >= 0 and z < bins say the same as floor(z) >= 0 and
        // floor(z) < bins, and the cast truncates z >= 0 to floor(z). Equal masses
        // give equal weights: the division is made once.
        double* bin = row->data();
        double m = 0, weight = 0;
        for (std::size_t k = 0; k < c.size; ++k) {
          const double z = ((c.v[k] - mean) * spec.scale + spec.zmax) / dz;
          if (c.m[k] != m) m = c.m[k], weight = m / density;
          if (z >= 0 && z < bins) bin[static_cast<std::size_t>(z)] += weight;
        }
      },
      Fields::velocities);
  return T / moments.mass;
}

}  // namespace shockgas::particles::detail
