#pragma once
// Clusters of a particle state: the particle side of "shocks are clusters".
//
// A cluster is a maximal run of ring neighbours i, i+1, ... such that every
// neighbouring pair in it is close and nearly co-moving:
//
//     gap_i = x_{i+1} - x_i < max_gap   and   |v_{i+1} - v_i| < max_dv
//
// (strict inequalities). On a ring of length L the pair (N-1, 0) is neighbours
// too, with gap x_0 + L - x_{N-1}, so a run may wrap across x = 0. A cluster's
// position is its centre of mass (members unrolled across the wrap, the result
// wrapped back into [0, L)), its velocity its momentum / mass.
//
// r = 0 (merging gas): every body is already a merged cluster and neighbouring
// bodies have gaps > 0, so each body is its own cluster: use
// merged_bodies_criteria(), which joins nothing.
//
// r > 0 with a threshold delta: see default_cluster_criteria().
#include <cstddef>
#include <vector>

#include "shockgas/core/bodies.hpp"

namespace shockgas::particles {

struct ClusterCriteria {
  double max_gap = 0.5;   // neighbours closer than this may share a cluster [length], >= 0
  double max_dv = 0.02;   // ... if their velocities differ by less than this [length/time], >= 0
};

struct Cluster {
  std::size_t first = 0;  // index of its first body (ring: the run may wrap past N-1 to 0)
  std::size_t count = 0;  // number of bodies in it
  double x = 0;           // centre of mass [length] (ring: in [0, L))
  double v = 0;           // momentum / mass [length/time]
  double m = 0;           // mass [mass]
};

// The clusters of b (sorted by x, positions in [0, L) on a ring), in order of
// their first body; every body belongs to exactly one cluster.
// L: ring length [length]; 0 = open line (no wrap). Throws InputError if L < 0,
// a criterion is negative or not finite, or b is not sorted / not inside [0, L).
std::vector<Cluster> find_clusters(const Bodies& b, double L, const ClusterCriteria& c);

// Default criteria for a gas with sub-threshold velocity delta and mean initial
// spacing `mean_spacing` (L / N):
//
//   max_dv  = 2 delta. Neighbours inside a cluster have stopped colliding
//             inelastically: their collisions are sub-threshold (|g| < delta),
//             elastic ones keep |g| < delta, so their relative velocities stay
//             below delta; the factor 2 leaves room for a pair that has just
//             exchanged velocity with a third member. Free particles differ by
//             ~ sqrt(T) >> delta.
//   max_gap = mean_spacing / 2. A settled cluster of n ~ t^(2/3) members spreads
//             at most ~ delta t (its members keep relative speeds < delta), so
//             its internal gaps are ~ delta t^(1/3) mean spacings: below 1/2 for
//             t < (2 delta)^(-3) = t_valid / 8 (t_valid ~ delta^(-3)). Two free
//             particles closer than half the initial spacing have been
//             compressed by a factor 2, which a pair rarely reaches with
//             |dv| < 2 delta unless it is in a cluster.
//
// delta = 0 gives max_dv = 0: nothing is joined (each body its own cluster).
// Throws InputError unless delta >= 0 and mean_spacing > 0 (both finite).
ClusterCriteria default_cluster_criteria(double delta, double mean_spacing);

// Criteria that join nothing: for merged bodies (r = 0), each is a cluster.
ClusterCriteria merged_bodies_criteria();

}  // namespace shockgas::particles
