// The count of clusters at the sample times (/particles/n_clusters) above
// particles.min_cluster_particles = k (MultiParticleRule): k = 2 the clusters
// of two or more particles, streamed; k > 2 those heavier than (k - 1/2) M / N,
// each sample walking the clusters. Either is the count of the clusters
// find_clusters finds in the state at that time by the default criteria.
#include <gtest/gtest.h>

#include <string>

#include "shockgas/core/error.hpp"
#include "shockgas/particles/cluster_finder.hpp"
#include "shockgas/particles/simulate.hpp"

namespace shockgas::particles {
namespace {

struct Case {
  double r;
  ParticleSolver solver;
  Geometry geometry;
  std::size_t threads;
};

std::string name(const Case& c) {
  return "r = " + std::to_string(c.r) + " " + std::string(name_of(c.solver)) + " " +
         std::string(name_of(c.geometry)) + " threads " + std::to_string(c.threads);
}

// Unit masses, mean spacing 1: M / N = 1.
RunResult run(const Case& c, double t_end, std::size_t k) {
  InitialParams ip;
  ip.N = 2000;
  ip.seed = 11;
  ParticleParams p;
  p.r = c.r;
  p.solver = c.solver;
  p.geometry = c.geometry;
  p.threads = c.threads;
  p.t_end = t_end;
  p.samples = 3;
  p.min_cluster_particles = k;
  const InitialCondition ic(ip);
  return simulate(ic.realization(0), ic.length(), p);
}

// The clusters of the final state holding k or more particles, found afresh.
double expected_count(const RunResult& r, const Case& c, std::size_t k) {
  const double L = c.geometry == Geometry::ring ? 2000.0 : 0.0;
  const ClusterCriteria criteria = gas_cluster_criteria(c.r, 0.01, 1.0, r.stop.time);
  double n = 0;
  for (const Cluster& cluster : find_clusters(r.final_state, L, criteria))
    n += k == 2 ? (cluster.count >= 2 || cluster.m > 1.5) : cluster.m > static_cast<double>(k) - 0.5;
  return n;
}

TEST(SampleClusterCount, IsTheCountOfTheClustersOfKOrMoreParticlesInTheStateAtThatTime) {
  const Case cases[] = {{0.0, ParticleSolver::hull, Geometry::ring, 1},
                        {0.0, ParticleSolver::events, Geometry::ring, 1},
                        {0.5, ParticleSolver::events, Geometry::ring, 1},
                        {0.5, ParticleSolver::events, Geometry::ring, 2},  // time windows in two domains
                        {0.5, ParticleSolver::events, Geometry::line, 1}};
  for (const Case& c : cases)
    for (double t_end : {30.0, 300.0}) {
      SCOPED_TRACE(name(c) + " t = " + std::to_string(t_end));
      double previous = 0;
      for (std::size_t k : {2u, 3u, 10u}) {
        const RunResult r = run(c, t_end, k);
        ASSERT_EQ(r.series.n_clusters.size(), 3u);
        const double expected = expected_count(r, c, k);
        EXPECT_EQ(r.series.n_clusters.back(), expected) << "k = " << k;
        // Not a count of nothing, and fewer as k grows (a gas at t = 30 holds
        // about 1.9 N t^(-2/3) = 400 shocks of about 5 particles).
        EXPECT_GT(expected, 0.0) << "k = " << k;
        if (k > 2) {
          EXPECT_LT(expected, previous) << "k = " << k;
        }
        previous = expected;
      }
    }
}

TEST(SampleClusterCount, KeepsTheRunOtherwiseTheSame) {
  const Case gas{0.5, ParticleSolver::events, Geometry::ring, 2};
  const RunResult two = run(gas, 100, 2), ten = run(gas, 100, 10);
  // k = 2 measures the samples in parts, each stretch's sums combined
  // (stretch_observables.hpp), k > 2 over the whole chain: T is the same sum of
  // squares in another order, equal to about N eps = 2e-13 of itself.
  ASSERT_EQ(two.series.T.size(), ten.series.T.size());
  for (std::size_t k = 0; k < two.series.T.size(); ++k)
    EXPECT_NEAR(ten.series.T[k], two.series.T[k], 1e-12 * two.series.T[k]);
  EXPECT_EQ(two.series.collisions, ten.series.collisions);
  EXPECT_EQ(two.final_state.x, ten.final_state.x);
  ASSERT_TRUE(two.final_clusters && ten.final_clusters);
  EXPECT_EQ(two.final_clusters->m, ten.final_clusters->m);  // the statistics see every cluster of >= 2
}

TEST(SampleClusterCount, FewerThanTwoParticlesIsRefusedNamingTheKey) {
  ParticleParams p;
  p.min_cluster_particles = 1;
  try {
    validate(p);
    FAIL() << "min_cluster_particles = 1 accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("particles.min_cluster_particles"), std::string::npos) << e.what();
  }
  EXPECT_THROW(MultiParticleRule(1.0, 1), InputError);
  EXPECT_EQ(MultiParticleRule(2.0, 10).heavy_mass(), 19.0);  // (k - 1/2) M / N
  EXPECT_TRUE(MultiParticleRule(1.0, 2).streams());
  EXPECT_FALSE(MultiParticleRule(1.0, 3).streams());
}

}  // namespace
}  // namespace shockgas::particles
