#pragma once
// One snapshot of "shocks are clusters": the particle state and the continuum
// field of the same initial condition at the same time t, compared. This is the
// composition the command writes to summary.json (compare.matched_mass_fraction,
// compare.sawtooth_slope_times_t, compare.n_shocks, compare.n_clusters); each
// step is a pure function of its own file:
//
//   particles ── find_clusters ──────────┐
//       └──── deposit_on_grid (fields) ──┼── match_shocks_to_clusters
//   continuum ── find_shocks ────────────┘       fit_sawtooth_slopes (between the shocks)
#include <cstddef>
#include <vector>

#include "shockgas/compare/deposit.hpp"
#include "shockgas/compare/matching.hpp"
#include "shockgas/compare/params.hpp"
#include "shockgas/compare/sawtooth.hpp"
#include "shockgas/compare/shock_detection.hpp"
#include "shockgas/continuum/field.hpp"
#include "shockgas/core/bodies.hpp"
#include "shockgas/particles/cluster_finder.hpp"

namespace shockgas::compare {

struct SnapshotParams {
  particles::ClusterCriteria clusters;                   // default_cluster_criteria(delta, L / N) for r > 0,
                                                         // merged_bodies_criteria() for r = 0
  ShockDetectionParams shocks;                           // used only if the solver has no shock list
  double match_distance = 0;                             // [length]; 0 = automatic (MatchParams)
  double min_cluster_particles = 2;                      // clusters and shocks lighter than this many mean
                                                         // particle masses (total mass / N) are ignored [1]
  SawtoothParams sawtooth;                               // ramp fits
  DepositScheme deposit = DepositScheme::cloud_in_cell;  // particles -> grid
};

struct SnapshotComparison {
  double t = 0;                              // time of both states [time]
  GridFields particle_fields;                // the particles on the continuum's grid
  std::vector<particles::Cluster> clusters;  // all clusters of the particle state
  std::vector<continuum::Shock> shocks;      // all shocks of the continuum field
  MatchResult match;                         // shocks <-> clusters (eligible ones)
  SawtoothFit sawtooth;                      // continuum v between its eligible shocks, cells with rho > 0
  SawtoothFit particle_sawtooth;             // deposited v on cells with mass, between the
                                             // extents (first to last body) of eligible clusters
  std::size_t n_shocks = 0;                  // eligible shocks
  std::size_t n_clusters = 0;                // eligible clusters
  double shock_count_ratio = 0;              // n_shocks / (N t^(-2/3))
  double min_mass = 0;                       // the eligibility threshold used [mass]
};

// The parameters of a scene's comparison at time t: the cluster criteria for a
// gas of restitution r and threshold delta with mean spacing L / N (merged bodies
// for r = 0), the scene's overrides, and the automatic eligibility threshold
// (theory.hpp) unless compare.min_cluster_particles is given.
SnapshotParams snapshot_params(const CompareParams& c, double r, double delta, double mean_spacing, double t);

// state: the particle state at field.t (positions in [0, field.length));
// N: number of initial particles. Throws InputError if N == 0, field has no
// cells, field.t <= 0 or a step rejects its input.
SnapshotComparison compare_snapshot(const Bodies& state, std::size_t N,
                                    const continuum::ContinuumResult& field,
                                    const SnapshotParams& params = {});

}  // namespace shockgas::compare
