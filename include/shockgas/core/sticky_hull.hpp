#pragma once
// The exact sticky-particle (adhesion) solution by the lower convex hull.
// API fixed here; implemented in core/sticky_hull.cpp.
//
// For point masses m_i at q_i with velocities u_i on a line, the state of the
// perfectly inelastic (merging) gas at time t is given by the lower convex hull
// of the cumulative points (M_k, S_k), M_k = sum_{i<=k} m_i,
// S_k = sum_{i<=k} m_i (q_i + t u_i): each hull edge is one cluster, its mass
// the edge's run of M, its position S-increment / mass-increment and its
// velocity the mass-weighted mean of its members (E, Rykov & Sinai 1996;
// Brenier & Grenier 1998).
#include <cstddef>
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

// Exact state at time t >= 0 of merging point masses on an open line.
// initial must be sorted by x. O(N).
std::vector<StickyCluster> sticky_clusters_line(const Bodies& initial, double t);

// The same on a ring of length L (initial positions in [0, L), sorted). The mean
// velocity is removed by a Galilean shift, the chain is unrolled periodically and
// the hull of the unrolled chain gives the clusters: one period of it, starting at
// a vertex found by a supporting line (see core/sticky_hull.cpp). O(N).
// Clusters are returned sorted by x; `first` + `count` may pass N - 1 (wrap).
//
// Both: clusters that exactly touch at t are not merged (they are from any later
// time on), so at t = 0 every body is its own cluster. Throws InputError for
// t < 0, unsorted or non-finite positions, masses <= 0, and (ring) L <= 0 or
// positions outside [0, L).
std::vector<StickyCluster> sticky_clusters_ring(const Bodies& initial, double L, double t);

// The clusters as bodies (x, v, m), sorted by x.
Bodies to_bodies(const std::vector<StickyCluster>& clusters);

}  // namespace shockgas
