#include <gtest/gtest.h>

#include <algorithm>

#include "shockgas/compare/matching.hpp"
#include "shockgas/compare/shock_detection.hpp"
#include "shockgas/core/error.hpp"
#include "shockgas/core/random.hpp"
#include "synthetic_fields.hpp"

namespace shockgas::compare {
namespace {

using particles::Cluster;

// Differences of O(100) positions: rounding ~ 1e-14; 1e-12 leaves room.
constexpr double kRound = 1e-12;

Cluster cluster_at(double x, double m, double v = 0) { return Cluster{0, 1, x, v, m}; }

TEST(Matching, SawtoothShocksMatchTheirClusters) {
  const auto saw = testing::five_shock_sawtooth();
  const auto field = saw.cell_averages(1000);
  const auto shocks = detect_shocks(field.v, field.rho, field.length);
  // Clusters where the sawtooth says, with known offsets, listed in a shuffled order.
  const std::vector<double> offset{0.01, -0.02, 0.03, -0.04, 0.05};
  const std::vector<std::size_t> order{3, 0, 4, 2, 1};
  std::vector<Cluster> clusters;
  for (std::size_t k : order) {
    double x = saw.X[k] + offset[k];
    if (x >= saw.L) x -= saw.L;  // 99.96 + 0.05 wraps to 0.01
    clusters.push_back(cluster_at(x, saw.mass(k), saw.shock_speed(k)));
  }
  const MatchResult r = match_shocks_to_clusters(shocks, clusters, saw.L, MatchParams{1.0, 0.0});
  ASSERT_EQ(r.pairs.size(), 5u);
  EXPECT_TRUE(r.unmatched_shocks.empty());
  EXPECT_TRUE(r.unmatched_clusters.empty());
  EXPECT_NEAR(r.matched_mass_fraction, 1.0, kRound);
  for (const MatchedPair& p : r.pairs) {
    EXPECT_EQ(order[p.cluster], p.shock);
    // Detection error (1e-10, see test_shock_detection) plus rounding.
    EXPECT_NEAR(p.position_error, offset[p.shock], 1e-9);
    EXPECT_NEAR(p.mass_error, 0.0, 1e-9);
    EXPECT_NEAR(p.velocity_error, 0.0, 1e-9);
  }
  EXPECT_NEAR(r.max_position_error, 0.05, 1e-9);
}

TEST(Matching, DistanceIsPeriodic) {
  const std::vector<continuum::Shock> shocks{{99.9, 3.0, -1.0, 0.0}};
  const std::vector<Cluster> clusters{cluster_at(0.05, 3.0)};
  const MatchResult r = match_shocks_to_clusters(shocks, clusters, 100.0, MatchParams{0.5, 0.0});
  ASSERT_EQ(r.pairs.size(), 1u);
  EXPECT_NEAR(r.pairs[0].position_error, 0.15, kRound);
  // And the other way round.
  const std::vector<continuum::Shock> shocks2{{0.05, 3.0, -1.0, 0.0}};
  const std::vector<Cluster> clusters2{cluster_at(99.9, 3.0)};
  const MatchResult r2 = match_shocks_to_clusters(shocks2, clusters2, 100.0, MatchParams{0.5, 0.0});
  ASSERT_EQ(r2.pairs.size(), 1u);
  EXPECT_NEAR(r2.pairs[0].position_error, -0.15, kRound);
}

TEST(Matching, OneToOneAndUnmatchedAreListed) {
  const std::vector<continuum::Shock> shocks{{10.0, 4.0, -1.0, 0.0}, {50.0, 2.0, -1.0, 0.0}};
  // Two clusters near the first shock (the closer wins), one far from both, one too light.
  const std::vector<Cluster> clusters{cluster_at(10.3, 1.0), cluster_at(9.9, 4.0), cluster_at(80.0, 5.0),
                                      cluster_at(50.0, 0.5)};
  const MatchResult r = match_shocks_to_clusters(shocks, clusters, 100.0, MatchParams{1.0, 1.0});
  ASSERT_EQ(r.pairs.size(), 1u);
  EXPECT_EQ(r.pairs[0].shock, 0u);
  EXPECT_EQ(r.pairs[0].cluster, 1u);
  EXPECT_EQ(r.unmatched_shocks, std::vector<std::size_t>{1});
  EXPECT_EQ(r.unmatched_clusters, (std::vector<std::size_t>{0, 2}));
  EXPECT_EQ(r.eligible_clusters, 3u);  // the 0.5 cluster is below min_mass
  EXPECT_NEAR(r.matched_mass_fraction, 4.0 / 10.0, kRound);
}

TEST(Matching, GreedyOnManyRandomPairsIsExact) {
  // 300 shocks at least 1 apart, each with its cluster displaced by < 0.25:
  // every pair is the unique candidate of its shock, so all match.
  Rng rng(17);
  const double L = 1000;
  std::vector<continuum::Shock> shocks;
  std::vector<Cluster> clusters;
  for (int k = 0; k < 300; ++k) {
    const double x = 3.0 * k + 2.0 * rng.uniform();
    shocks.push_back(continuum::Shock{x, 1.0 + k, -1.0, 0.0});
    double xc = x + 0.5 * (rng.uniform() - 0.5);
    if (xc < 0) xc += L;
    clusters.push_back(cluster_at(xc, 1.0 + k));
  }
  std::reverse(clusters.begin(), clusters.end());
  const MatchResult r = match_shocks_to_clusters(shocks, clusters, L, MatchParams{0.3, 0.0});
  ASSERT_EQ(r.pairs.size(), 300u);
  for (const MatchedPair& p : r.pairs) EXPECT_EQ(p.cluster, 299 - p.shock);
  EXPECT_NEAR(r.matched_mass_fraction, 1.0, kRound);
}

TEST(Matching, AutomaticDistanceIsAQuarterOfTheShockSpacing) {
  // Four shocks on a ring of 100: automatic distance 100 / 16 = 6.25. A cluster
  // 6 away matches, one 7 away does not.
  const std::vector<continuum::Shock> shocks{{10, 1, -1, 0}, {35, 1, -1, 0}, {60, 1, -1, 0}, {85, 1, -1, 0}};
  const std::vector<Cluster> clusters{cluster_at(16.0, 1.0), cluster_at(42.0, 1.0)};
  const MatchResult r = match_shocks_to_clusters(shocks, clusters, 100.0);
  EXPECT_DOUBLE_EQ(r.max_distance, 6.25);
  ASSERT_EQ(r.pairs.size(), 1u);
  EXPECT_EQ(r.pairs[0].cluster, 0u);
  EXPECT_EQ(r.unmatched_clusters, std::vector<std::size_t>{1});
}

TEST(Matching, RejectsBadParameters) {
  EXPECT_THROW(match_shocks_to_clusters({}, {}, 0.0), InputError);
  EXPECT_THROW(match_shocks_to_clusters({}, {}, 1.0, MatchParams{-1.0, 0.0}), InputError);
  EXPECT_THROW(match_shocks_to_clusters({}, {}, 1.0, MatchParams{1.0, -1.0}), InputError);
}

}  // namespace
}  // namespace shockgas::compare
