#pragma once
// Shocks of the continuum matched one-to-one to clusters of the particle gas on
// the ring: the figure of merit of "shocks are clusters".
//
// Distances are periodic: d(a, b) = b - a wrapped into [-L/2, L/2). Only shocks
// and clusters of mass >= min_mass take part (a lone particle is not a cluster,
// a numerical wiggle is not a shock). Candidate pairs are those with
// |d| <= max_distance; they are accepted greedily in order of increasing |d|
// (ties by shock then cluster index) while both ends are free. Greedy is the
// optimal assignment whenever each shock has a single cluster within
// max_distance, which holds when max_distance is below half the spacing of the
// shocks; it never pairs across a closer free candidate.
//
// matched_mass_fraction = (mass of matched clusters) / (mass of all clusters
// with m >= min_mass); 1 when every cluster has its shock.
#include <cstddef>
#include <vector>

#include "shockgas/continuum/field.hpp"
#include "shockgas/particles/cluster_finder.hpp"

namespace shockgas::compare {

struct MatchParams {
  double max_distance = 0.0;  // largest |x_cluster - x_shock| of a pair [length], >= 0;
                              // 0 = automatic: L / (4 n), n = number of eligible shocks
                              // (a quarter of their mean spacing: greedy is then optimal)
  double min_mass = 0.0;      // shocks and clusters lighter than this are ignored [mass], >= 0
};

struct MatchedPair {
  std::size_t shock = 0;      // index into the shock list
  std::size_t cluster = 0;    // index into the cluster list
  double position_error = 0;  // x_cluster - x_shock, periodic, in [-L/2, L/2) [length]
  double mass_error = 0;      // m_cluster - mass_shock [mass]
  double velocity_error = 0;  // v_cluster - v_shock [length/time]
};

struct MatchResult {
  std::vector<MatchedPair> pairs;               // sorted by shock index
  std::vector<std::size_t> unmatched_shocks;    // indices of eligible shocks without a cluster
  std::vector<std::size_t> unmatched_clusters;  // indices of eligible clusters without a shock
  std::size_t eligible_shocks = 0;              // shocks with mass >= min_mass
  std::size_t eligible_clusters = 0;            // clusters with m >= min_mass
  double cluster_mass = 0;                      // mass of eligible clusters [mass]
  double matched_cluster_mass = 0;              // mass of matched clusters [mass]
  double matched_mass_fraction = 0;             // matched_cluster_mass / cluster_mass (0 if none)
  double max_position_error = 0;                // max |position_error| over pairs [length]
  double rms_position_error = 0;                // root mean square over pairs [length]
  double max_distance = 0;                      // the matching distance used [length]
  double max_relative_mass_error = 0;           // max |mass_error| / m_cluster over pairs [1]
  double rms_velocity_error = 0;                // root mean square over pairs [length/time]
};

// Throws InputError if L <= 0, max_distance < 0 or min_mass < 0.
MatchResult match_shocks_to_clusters(const std::vector<continuum::Shock>& shocks,
                                     const std::vector<particles::Cluster>& clusters, double L,
                                     const MatchParams& params = {});

// Periodic displacement b - a on a ring of length L, in [-L/2, L/2).
double periodic_displacement(double a, double b, double L);

}  // namespace shockgas::compare
