#include "chain_observables.hpp"

#include <cmath>

namespace shockgas::particles::detail {

ClusterCounter::ClusterCounter(double L, bool ring, const ClusterCriteria& criteria)
    : L_(L), ring_(ring), criteria_(criteria) {}

void ClusterCounter::add(const ChainChunk& chunk) {
  for (std::size_t k = 0; k < chunk.size; ++k) add(chunk.x[k], chunk.v[k]);
}

void ClusterCounter::add(double x, double v) {
  const double w = ring_ ? wrap_into(x, L_) : x;
  if (bodies_++ == 0) {
    x0_ = w, v0_ = v;
  } else {
    double gap = w - last_x_;
    if (w < last_x_) {
      if (ring_ && !seam_)
        seam_ = true, gap = w + L_ - last_x_;  // the ring's wrapping pair
      else
        ordered_ = false;
    }
    joined_ += criteria_.joins(gap, v - last_v_);
  }
  last_x_ = w, last_v_ = v;
}

std::optional<std::size_t> ClusterCounter::count() const {
  if (!ring_) return ordered_ ? std::optional(bodies_ - joined_) : std::nullopt;
  if (bodies_ < 2) return bodies_;
  // The pair (last, first) closes the ring: the wrapping pair if the positions
  // never dropped, else an ordinary pair that must be in order.
  const bool ordered = ordered_ && (!seam_ || x0_ >= last_x_);
  if (!ordered) return std::nullopt;
  const double gap = seam_ ? x0_ - last_x_ : x0_ + L_ - last_x_;
  const std::size_t joined = joined_ + criteria_.joins(gap, v0_ - last_v_);
  return joined < bodies_ ? bodies_ - joined : 1;  // a fully joined ring is one cluster
}

ChainMoments chain_moments(const ChainView& chain, ClusterCounter* counter) {
  ChainMoments s;
  chain.visit([&](const ChainChunk& c) {
    for (std::size_t k = 0; k < c.size; ++k) s.mass += c.m[k], s.momentum += c.m[k] * c.v[k];
    if (counter) counter->add(c);
  });
  return s;
}

double chain_temperature(const ChainView& chain, const ChainMoments& moments, const HistogramSpec& spec,
                         std::vector<double>* row) {
  const double mean = moments.mean();
  const double dz = 2 * spec.zmax / static_cast<double>(spec.bins);
  const double bins = static_cast<double>(spec.bins);
  if (row) row->assign(spec.bins, 0.0);
  double T = 0;
  chain.visit([&](const ChainChunk& c) {
    for (std::size_t k = 0; k < c.size; ++k) T += c.m[k] * (c.v[k] - mean) * (c.v[k] - mean);
    if (!row) return;
    for (std::size_t k = 0; k < c.size; ++k) {
      const double bin = std::floor(((c.v[k] - mean) * spec.scale + spec.zmax) / dz);
      if (bin >= 0 && bin < bins) (*row)[static_cast<std::size_t>(bin)] += c.m[k] / (moments.mass * dz);
    }
  });
  return T / moments.mass;
}

}  // namespace shockgas::particles::detail
