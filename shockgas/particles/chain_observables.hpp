#pragma once
// The observables of one sample, streamed over the chain (private to particles/):
// no copy of the state, no sort. Two passes, each reading every body once:
//
//  1. mass M = sum m, momentum P = sum m v, and the number of clusters counted;
//  2. T = sum m (v - <v>)^2 / M about the mean <v> = P / M of pass 1 (no
//     cancellation), and the mass-weighted histogram of z = (v - <v>) t^(1/3).
//
// The sums run in chain order, the cluster criteria compare the same numbers:
// every value equals, to the bit, that of the sorted copy the recorder used to
// make (sorted_bodies, then find_clusters).
#include <cstddef>
#include <optional>
#include <vector>

#include "shockgas/particles/chain_view.hpp"
#include "shockgas/particles/cluster_finder.hpp"
#include "shockgas/particles/lone_bodies.hpp"
#include "shockgas/particles/ring_wrap.hpp"

namespace shockgas::particles::detail {

// The clusters of find_clusters(sorted_bodies(chain), L, criteria) that `rule`
// counts, in one pass over the chain. The bodies never pass each other, so the
// chain sorted by x is the chain itself, rotated on a ring where the wrapped
// positions drop back (the seam): each pair of chain neighbours is a pair of
// neighbours in x, the one at the seam the ring's wrapping pair (gap x_first + L
// - x_last). The clusters are the bodies less the joined pairs, those counted
// the clusters less the lone light bodies (lone_bodies.hpp). Rounding can leave
// two touching bodies out of order (a second drop); the count is then refused,
// and the caller sorts as before.
class ClusterCounter {
 public:
  // L: ring length (line: unused); ring: wrap positions into [0, L).
  ClusterCounter(double L, bool ring, const ClusterCriteria& criteria, const MultiParticleRule& rule);
  void add(const ChainChunk& chunk);
  // The number of clusters counted; nullopt if the wrapped chain was not in order.
  std::optional<std::size_t> count() const;

 private:
  double L_;
  bool ring_;
  ClusterCriteria criteria_;
  MultiParticleRule rule_;
  PeriodWrap wrap_;
  std::size_t bodies_ = 0, joined_ = 0;
  LoneBodies lone_;
  bool seam_ = false;       // the wrapped positions dropped once (ring)
  bool ordered_ = true;     // ... and never again
  double x0_ = 0, v0_ = 0;  // first body (wrapped)
  double last_x_ = 0, last_v_ = 0;
};

// Sums of pass 1.
struct ChainMoments {
  double mass = 0;      // [mass]
  double momentum = 0;  // [mass length/time]
  double mean() const { return momentum / mass; }
};

// Pass 1: moments; clusters counted into *counter unless it is null.
ChainMoments chain_moments(const ChainView& chain, ClusterCounter* counter);

// Mass-weighted histogram of z = (v - mean) scale in `bins` bins on [-zmax, zmax]:
// the mass fraction in each bin over the bin width (ScaledHistogram).
struct HistogramSpec {
  std::size_t bins = 0;
  double zmax = 0;   // [length/time^(2/3)]
  double scale = 0;  // t^(1/3) [time^(1/3)]
};

// Pass 2: the temperature sum m (v - mean)^2 / M; the histogram row is filled
// into *row (resized to spec.bins) unless row is null.
double chain_temperature(const ChainView& chain, const ChainMoments& moments, const HistogramSpec& spec,
                         std::vector<double>* row);

}  // namespace shockgas::particles::detail
