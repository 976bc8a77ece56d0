#pragma once
// The statistics of the shocks of a gas over many realizations (`shockgas stats`):
// each realization's clusters of at least two particles at one time t
// (particles::RunResult::final_clusters), reduced to
//
//   the number per realization,                       n,
//   the mass distribution in bins 1.5, 2.5, 4.5, ... particles (clusters per bin per realization),
//   the mass-weighted velocity distribution of z = (v - U) t^(1/3)  (U: the realization's mean),
//   the spacing between neighbouring clusters, in units of the realization's mean spacing L / n,
//   the correlation of mass with speed |v - U| (Pearson, over all clusters),
//
// each with its error from the realizations, which are independent: the
// delete-one jackknife (jackknife.hpp; for a mean it is s / sqrt(R)). One
// realization gives no error (NaN, "no error estimate from one realization").
//
// For white noise on a lattice (white_noise_references.hpp) the exact laws of
// Burgers turbulence apply (the sticky gas at r = 0 follows them; the gas at
// r > 0 approaches them in its sticky regime): the shock-mass law
// (shock_mass_law.hpp) for the counts, held by Pearson's chi-square on the
// counts summed over realizations (Poisson in each bin; bins merged from the
// heavy end until each expects >= 5), and the mass-weighted cluster velocity
// law (cluster_velocity_law.hpp) for z, held by the chi-square of the bins'
// means against it with their jackknife errors (dof = bins - 1: the mass
// fractions sum to one). The spacing and the correlation have no exact law
// here: they are measured, not tested.
#include <cstddef>
#include <optional>
#include <vector>

#include "shockgas/compare/jackknife.hpp"
#include "shockgas/core/bodies.hpp"

namespace shockgas::compare {

// What the realizations are of: each holds N particles of total mass M on a
// ring (or line) of length L, observed at time t.
struct StatisticsShape {
  double N = 0;                         // particles per realization [1]
  double mass = 0;                      // M [mass]
  double L = 0;                         // [length]
  double t = 0;                         // [time]
  bool ring = true;                     // neighbours across the wrap
  std::optional<double> white_noise_D;  // the intensity D when the start is white noise [length^3/time^2]
};

// Binning of the distributions: one declaration.
inline constexpr double kStatisticsZMax = 3.0;        // z bins on [-zmax, zmax] [length/time^(2/3)]
inline constexpr std::size_t kStatisticsZBins = 30;   // bins of z
inline constexpr double kStatisticsSpacingMax = 4.0;  // spacing bins on [0, max] mean spacings
inline constexpr std::size_t kStatisticsSpacingBins = 20;

// A distribution over bins: each bin's value with its error, the exact value
// where a law applies, and the chi-square against it.
struct BinnedStatistic {
  std::vector<double> edges;  // bins.size() + 1 edges
  std::vector<double> value;  // per bin
  std::vector<double> error;  // jackknife; NaN from one realization, or in a bin empty in every one
  std::vector<double> exact;  // per bin; empty without an exact law
  // The chi-square of value against exact (when exact is given and it can be
  // formed: enough realizations or counts).
  std::optional<double> chi2;
  std::size_t dof = 0;
  std::optional<double> p_value;
  std::size_t bins_tested = 0;  // after merging sparse bins (mass) or dropping empty ones (z)
};

struct ShockStatistics {
  StatisticsShape shape;
  std::size_t realizations = 0;
  std::size_t clusters = 0;                  // over all realizations
  JackknifeEstimate count;                   // clusters per realization
  std::optional<double> count_exact;         // the exact expectation of shocks above 1.5 particles
  BinnedStatistic mass;                      // clusters per realization per mass bin [particles]
  BinnedStatistic velocity;                  // mass fraction per unit z [time^(2/3)/length]
  BinnedStatistic spacing;                   // fraction of neighbour gaps per unit mean spacing [1]
  JackknifeEstimate mass_speed_correlation;  // Pearson r of m and |v - U| over all clusters
};

// Mass bin edges 1.5, 2.5, 4.5, ..., 2^k + 0.5 [particles] up to past `heaviest`:
// each bin holds whole particle numbers, twice as many as the one before.
std::vector<double> doubling_mass_edges(double heaviest);

// The statistics of `realizations` (each sorted by x: centre of mass, velocity,
// mass of its clusters of >= 2 particles). Throws InputError unless there is at
// least one realization and the shape is positive.
ShockStatistics shock_statistics(const std::vector<Bodies>& realizations, const StatisticsShape& shape);

}  // namespace shockgas::compare
