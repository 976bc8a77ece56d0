// An inelastic gas of r = 0.5 from white noise (2 10^4 particles to t = 10^4, as
// data/scenes/default.toml starts) counts in time the shocks of Burgers
// turbulence that hold two or more particles once its clusters have gathered
// the sticky gas's mass (cluster_count_law.hpp), and its heavy clusters are the
// sticky gas's where delta keeps them narrow. (The default scene itself:
// tests/app/test_default_scene_slow.cpp.)
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "cluster_count_law.hpp"

namespace shockgas::compare {
namespace {

using namespace testing;

// 10 realizations (samples at 1, 10, ..., 10^3, 10^3.5, 10^4). At t = 10^4 the
// mean count lies within 3 standard errors of the exact count of shocks
// heavier than 1.5 particles (measured: 75.6 +- 3.4 against 79.2; a two-sided
// Student t of 9 degrees of freedom exceeds 3 with probability 1.5 %). Before,
// from t = 10^3 on, it approaches from below (measured: 12 % below at 10^3,
// 14 % at 10^3.5, 5 % at 10^4): shocks of a few particles are still pairs that bounce
// apart faster than delta, and some particles are not yet in a cluster
// (docs/validate.md) -- never above by more than 3 standard errors. A count
// with lone particles (1.0 10^3 at t = 10^3, 1.6 10^3 at 10^4) fails both.
TEST(ClusterCountLaw, GasOfDeltaOneHundredthCountsTheShocksOfTwoOrMoreParticlesAtItsEnd) {
  const InitialParams ip = white_noise(20000);
  particles::ParticleParams p;
  p.r = 0.5;
  p.delta = 1e-2;
  p.t_end = 1e4;
  p.samples = 9;
  p.realizations = 10;
  const particles::EnsembleResult e = particles::run_ensemble(ip, p);
  const WhiteNoiseReferences w = *white_noise_references(ip);
  ASSERT_EQ(e.t.size(), 9u);
  ASSERT_EQ(e.count.back(), 10.0);  // every realization reached t = 10^4
  EXPECT_EQ(expect_counts_the_shocks(e, w, e.t.back(), 3.0), 1u);
  for (std::size_t k = 0; k < e.t.size(); ++k) {
    if (e.t[k] < 1e3 - 1e-9) continue;
    EXPECT_LT(e.n_clusters.mean[k], shocks_of_two_or_more(w, e.t[k]) + 3 * e.n_clusters.stderr_[k])
        << "t = " << e.t[k];
  }
}

// Realization k's clusters of at least `particles` unit-mass particles at its end.
std::vector<double> heavy_clusters(const particles::EnsembleResult& e, double particles) {
  std::vector<double> counts;
  for (const auto& clusters : e.final_clusters) {
    EXPECT_TRUE(clusters.has_value());
    counts.push_back(clusters
                         ? static_cast<double>(std::count_if(clusters->m.begin(), clusters->m.end(),
                                                             [&](double m) { return m > particles - 0.5; }))
                         : 0.0);
  }
  return counts;
}

// The mean of gas - hull over realizations, and its standard error.
std::pair<double, double> paired_difference(const std::vector<double>& gas, const std::vector<double>& hull) {
  const double n = static_cast<double>(gas.size());
  double mean = 0, square = 0;
  for (std::size_t k = 0; k < gas.size(); ++k) mean += (gas[k] - hull[k]) / n;
  for (std::size_t k = 0; k < gas.size(); ++k) square += std::pow(gas[k] - hull[k] - mean, 2);
  return {mean, std::sqrt(square / (n - 1) / n)};
}

// Where the gas's count of the heavy clusters stands against the exact sticky
// solution of the same starts (the hull at r = 0, realization by realization):
// 6 realizations of the default scene's start to t = 3 10^3, clusters of at
// least 10 particles (about 150 per realization; the shocks of a few
// particles are the slow part of the approach, docs/validate.md). With
// delta = 10^-2 the gas holds fewer: measured 17.7 +- 2.8 per realization
// fewer (815 against 921 in all, 0.885 of them), more than 5 standard errors
// of the paired difference; a gas's cluster spreads to about delta t (30 at
// t = 3 10^3, against 130 between heavy clusters), and two of them meet
// before their shocks would. With delta = 3 10^-3 they are the sticky gas's within 3
// standard errors (measured: -0.7 +- 2.0 per realization, 917 against 921;
// Student's t of 5 degrees of freedom exceeds 3 with probability 3 %).
TEST(ClusterCountLaw, HeavyClustersFollowTheStickyGasOnlyWhereDeltaKeepsThemNarrow) {
  const InitialParams ip = white_noise(20000);
  particles::ParticleParams p;
  p.t_end = 3e3;
  p.samples = 2;
  p.realizations = 6;
  p.final_clusters = particles::ClusterRecord::always;
  particles::ParticleParams sticky = p;
  sticky.r = 0.0;
  sticky.solver = particles::ParticleSolver::hull;
  const std::vector<double> hull = heavy_clusters(particles::run_ensemble(ip, sticky), 10);
  p.r = 0.5;
  p.delta = 1e-2;
  const auto [loose, loose_error] =
      paired_difference(heavy_clusters(particles::run_ensemble(ip, p), 10), hull);
  EXPECT_LT(loose, -5 * loose_error) << loose << " +- " << loose_error;
  p.delta = 3e-3;
  const auto [narrow, narrow_error] =
      paired_difference(heavy_clusters(particles::run_ensemble(ip, p), 10), hull);
  EXPECT_LT(std::abs(narrow), 3 * narrow_error) << narrow << " +- " << narrow_error;
}

}  // namespace
}  // namespace shockgas::compare
