#pragma once
// The exact sticky-particle (adhesion) solution by the lower convex hull.
// Implemented in shockgas/core/sticky_hull.cpp.
//
// For point masses m_i at q_i with velocities u_i on a line, the state of the
// perfectly inelastic (merging) gas at time t is given by the lower convex hull
// of the cumulative points (M_k, S_k), M_k = sum_{i<=k} m_i,
// S_k = sum_{i<=k} m_i (q_i + t u_i): each hull edge is one cluster, its mass
// the edge's run of M, its position S-increment / mass-increment and its
// velocity the mass-weighted mean of its members (E, Rykov & Sinai 1996;
// Brenier & Grenier 1998). Clusters only merge: the partition at a later time
// coarsens the one at an earlier time, so the later state is the hull of the
// earlier clusters taken as bodies (StickyHull::advance). Clusters that meet at
// exactly t (same position, the left one faster) are one at t, as the event
// engine has collided them by then; coincident ones that separate are not.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "shockgas/core/bodies.hpp"

namespace shockgas {

struct StickyCluster {
  double x = 0;           // position at time t [length] (ring: wrapped into [0, L))
  double v = 0;           // velocity [length/time]
  double m = 0;           // mass [mass]
  std::size_t first = 0;  // index of its first initial body (ring: may wrap past N-1)
  std::size_t count = 0;  // number of initial bodies in it
};

// The clusters of a sticky gas at one time, in chain order, kept as runs of
// (centre of mass at t = 0, velocity, number of bodies) and, for unequal masses,
// the mass: 20 bytes per cluster (28 with unequal masses), no copy of the bodies.
// Building costs one pass over the bodies; advancing to a later time one pass
// over the clusters, in place.
//
//   StickyHull h = StickyHull::ring(initial, L, 1.0);
//   h.advance(10.0);                                   // = StickyHull::ring(initial, L, 10.0)
//   h.for_each([](const StickyCluster& c) { ... });    // chain order
class StickyHull {
 public:
  // The clusters at time t >= 0 of `initial` (sorted by x) on an open line.
  // Throws InputError for t < 0, unsorted or non-finite positions, masses <= 0,
  // or more than 2^32 - 1 bodies.
  static StickyHull line(BodiesView initial, double t);
  // The same on a ring of length L > 0 (positions in [0, L)).
  static StickyHull ring(BodiesView initial, double L, double t);
  // The same from n bodies of one mass read a chunk at a time, never held
  // whole: read(count, x, v, m) writes the next count of them. InputError as
  // above, and for unequal masses.
  using Chunks = std::function<void(std::size_t count, double* x, double* v, double* m)>;
  static StickyHull line(std::size_t n, const Chunks& read, double t);
  static StickyHull ring(std::size_t n, const Chunks& read, double L, double t);

  // The clusters at time t >= time(). Throws InputError for t < time().
  void advance(double t);

  double time() const { return t_; }
  std::size_t size() const { return end_ - begin_; }  // clusters
  std::size_t bodies() const { return n_; }
  // Bytes each cluster occupies while it is held.
  std::size_t bytes_per_cluster() const { return masses_ ? 28 : 20; }

  // Visits the clusters in chain order: f(const StickyCluster&), first running
  // from the lowest index; on a ring the last cluster may wrap past N - 1 and
  // its x is then unrolled (in [0, 2L)); else x is the position at time().
  template <class F>
  void for_each(F&& f) const {
    std::size_t first = origin_;
    for (std::size_t k = begin_; k < end_; ++k) {
      f(StickyCluster{c0_[k] + t_ * v_[k], v_[k], mass(k), first, count_[k]});
      first += count_[k];
      if (first >= n_) first -= n_;
    }
  }

  // Visits the clusters in order of x: f(const StickyCluster&), x at time()
  // (ring: wrapped into [0, L)). clusters() without the vector.
  template <class F>
  void for_each_by_x(F&& f) const {
    const Start s = lowest();
    std::size_t first = s.first;
    for (std::size_t j = 0, k = s.run; j < size(); ++j, k = k + 1 == end_ ? begin_ : k + 1) {
      f(StickyCluster{wrapped(c0_[k] + t_ * v_[k]), v_[k], mass(k), first, count_[k]});
      first += count_[k];
      if (first >= n_) first -= n_;
    }
  }

  // The clusters sorted by x (ring: wrapped into [0, L)).
  std::vector<StickyCluster> clusters() const;

 private:
  StickyHull(std::size_t n, double L, double t, bool masses);
  static StickyHull make(BodiesView initial, double L, double t);  // L = 0: line
  static StickyHull make(std::size_t n, const Chunks& read, double L, double t);
  enum class Built { ok, unequal_masses, bad_input };
  struct BlockPointers {
    const double *x, *v, *m;
  };
  template <bool Masses, class Block>
  Built build(Block&& block);
  template <bool Masses>
  void pool_runs();
  void close_ring();
  // InputError naming t when x + t v could leave the range of doubles.
  void check_reach(double t) const;
  double mass(std::size_t k) const { return masses_ ? m_[k] : m0_ * count_[k]; }
  // x wrapped into [0, L) on a ring; unchanged on a line.
  double wrapped(double x) const {
    if (L_ <= 0) return x;
    double w = std::fmod(x, L_);
    if (w < 0) w += L_;
    return w >= L_ ? 0.0 : w;
  }
  // The run of lowest wrapped x (the first such in chain order), and its first body.
  struct Start {
    std::size_t run = 0, first = 0;
  };
  Start lowest() const;

  std::size_t n_;
  double L_;  // ring length; 0 = open line
  double t_;
  bool masses_;         // masses differ: m_ holds them
  double m0_ = 0;       // the mass of every body, if they are equal
  double reach_x_ = 0;  // max |x| at t = 0, plus L on a ring (unrolled centres): check_reach
  double vmax_ = 0;     // max |v|
  std::size_t origin_ = 0, begin_ = 0,
              end_ = 0;                     // index of the first body of run begin_; runs [begin_, end_)
  std::unique_ptr<double[]> c0_, v_, m_;    // centre of mass at t = 0 (unrolled), velocity, mass
  std::unique_ptr<std::uint32_t[]> count_;  // bodies per run
};

// Exact state at time t >= 0 of merging point masses on an open line.
// initial must be sorted by x. O(N). Clusters sorted by x.
std::vector<StickyCluster> sticky_clusters_line(BodiesView initial, double t);

// The same on a ring of length L (initial positions in [0, L), sorted). O(N).
// Clusters are returned sorted by x; `first` + `count` may pass N - 1 (wrap).
//
// Both: clusters at the same point at t are one if they approach (they collide at
// exactly t, as the engine has by then), two if they separate. Throws InputError for
// t < 0, unsorted or non-finite positions, masses <= 0, and (ring) L <= 0 or
// positions outside [0, L).
std::vector<StickyCluster> sticky_clusters_ring(BodiesView initial, double L, double t);

// The clusters as bodies (x, v, m), sorted by x.
Bodies to_bodies(const std::vector<StickyCluster>& clusters);

}  // namespace shockgas
