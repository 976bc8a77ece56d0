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
#include <cmath>
#include <cstddef>
#include <functional>
#include <optional>
#include <vector>

#include "shockgas/core/bodies.hpp"
#include "shockgas/particles/state_sink.hpp"

namespace shockgas::particles {

struct ClusterCriteria {
  double max_gap = 0.5;  // neighbours closer than this may share a cluster [length], >= 0
  double max_dv = 0.02;  // ... if their velocities differ by less than this [length/time], >= 0

  // Whether neighbours `gap` apart (right minus left) with velocities differing
  // by dv belong to one cluster: gap < max_gap and |dv| < max_dv (both tested:
  // no branch to mispredict when streaming).
  bool joins(double gap, double dv) const { return (gap < max_gap) & (std::abs(dv) < max_dv); }
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

// The clusters of find_clusters(state, L, c), bit for bit and in the same
// order, handed to visit one at a time from a state read in chunks (one read
// on a line, and on a ring where the state knows its last body and at most
// 2^16 bodies lie before the walk's start; else two, or three when the start
// is past body 0), never held whole. The state must be what
// find_clusters accepts (sorted; ring: in [0, L)); the criteria are checked.
void visit_clusters(const StateReader& state, double L, const ClusterCriteria& c,
                    const std::function<void(const Cluster&)>& visit);
// The heaviest of those clusters, the first of the heaviest in their order (as
// a max_element over them picks it), by the same walk without making the
// lighter ones; none for an empty state.
std::optional<Cluster> heaviest_cluster(const StateReader& state, double L, const ClusterCriteria& c);

// Default criteria for a gas with sub-threshold velocity delta and mean initial
// spacing a = L / N, at time t (the sticky regime, t_stick << t < t_valid ~ delta^-3):
//
//   max_gap = max(a / 2, sqrt(delta t a)).
//             Two length scales: a settled cluster keeps relative speeds
//             ~ delta among its members and spreads to ~ delta t, so its
//             n ~ (t / tau)^(2/3) members (tau = a / v0) are ~ g_in = delta t / n
//             apart, while clusters are l = a n apart. The geometric mean
//             sqrt(g_in l) = sqrt(delta t a) sits between them (their ratio
//             l / g_in = (t / tau)^(1/3) v0 / delta grows with t) and needs no
//             velocity scale. Floor a / 2: closer than half the initial spacing
//             only after compression. On the default scene (N = 2e4, delta = 1e-2,
//             t = 1e4: max_gap = 10) it gives 70 clusters of >= 2 particles
//             against 70 exact shocks at r = 0.5; a / 2 alone gives 886
//             fragments (measured gaps inside clusters: median 0.03, 95% < 0.8,
//             99% < 3.3; between clusters mostly > 10).
//   max_dv  = 5 delta. Neighbours in a cluster collide sub-threshold
//             (|g| < delta) and keep |g| < delta, except just after an inelastic
//             collision (separating at r g); measured there, 99% of close pairs
//             have |dv| < 0.7 delta, and free particles meet clusters at the
//             shock jumps ~ v0 (tau / t)^(1/3) >> delta (0.046 at t = 1e4).
//
// delta = 0 gives max_dv = 0: nothing is joined (each body its own cluster).
// Throws InputError unless delta >= 0, mean_spacing > 0 and t >= 0 (finite).
ClusterCriteria default_cluster_criteria(double delta, double mean_spacing, double t);

// The same without a time: max_gap = a / 2 (the early-time floor), max_dv = 5 delta.
// Prefer the three-argument form for a late-time state.
ClusterCriteria default_cluster_criteria(double delta, double mean_spacing);

// Criteria that join nothing: for merged bodies (r = 0), each is a cluster.
ClusterCriteria merged_bodies_criteria();

// The criteria every count of a gas's clusters uses (the time series, the final
// clusters, the comparison, the lab): where every collision merges (r = 0,
// CollisionRule::merges_only) the bodies are the clusters, merged_bodies_criteria();
// else default_cluster_criteria(delta, mean_spacing, t).
ClusterCriteria gas_cluster_criteria(double r, double delta, double mean_spacing, double t);

// The clusters that hold at least k particles (k >= 2; 2 unless a scene asks
// for more: particles.min_cluster_particles): what the time series counts
// (/particles/n_clusters), the particle side of the shocks, of which a lone
// particle is none.
//
// k = 2: a cluster of two or more bodies holds two or more particles; a lone
// body only if particles merged into it (r = 0, or a sticky sub-threshold
// rule). With particles of equal mass M / N a merged body weighs at least
// 2 M / N and a particle M / N: a lone body counts when heavier than 1.5 M / N,
// between the two, far from either's rounding. With equal particle masses this
// is "cluster mass > 1.5 M / N"; body count first rather than mass alone
// because with unequal masses (a density rho0) a cluster of two light particles
// is still counted (a lone heavy particle then counts too, a merged pair of
// light ones not: the bodies carry no particle count), and because a body is
// decided from its own mass and its two pairs, so a stream over the chain needs
// no running sum of a cluster's mass (chain_observables.hpp,
// stretch_observables.hpp): streams().
//
// k > 2: a cluster counts when its mass exceeds (k - 1/2) M / N, halfway
// between k - 1 and k particles of equal mass (the exact shock count above the
// same mass is its expectation for a white-noise start, shock_mass_law.hpp).
// That needs each cluster's mass: the clusters are walked (visit_clusters).
class MultiParticleRule {
 public:
  // mean_particle_mass: M / N of the run's initial particles [mass]; k: the
  // fewest particles a counted cluster holds. Throws InputError unless the mass
  // is finite and > 0 and k >= 2.
  explicit MultiParticleRule(double mean_particle_mass, std::size_t k = 2);
  // Whether a lone body of mass m holds k or more particles.
  bool heavy(double m) const { return m > heavy_mass_; }
  // Whether cluster c holds k or more particles.
  bool counts(const Cluster& c) const { return (body_count_counts_ && c.count >= 2) || heavy(c.m); }
  // (k - 1/2) M / N [mass]: heavy(m) is m > heavy_mass() (for a stream's own comparisons).
  double heavy_mass() const { return heavy_mass_; }
  // Whether a body is decided by its own mass and its two pairs (k = 2), so
  // that a stream over the chain can count the clusters without their masses.
  bool streams() const { return body_count_counts_; }

 private:
  double heavy_mass_;       // (k - 1/2) M / N [mass]
  bool body_count_counts_;  // k = 2: two bodies are two particles
};

}  // namespace shockgas::particles
