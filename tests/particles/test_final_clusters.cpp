// Each realization's clusters of at least two particles at its end
// (RunResult::final_clusters): the clusters find_clusters finds in the final
// state by the default criteria at t_end, those heavier than 1.5 particles, in
// order of x; recorded as particles.final_clusters says.
#include <gtest/gtest.h>

#include <algorithm>

#include "shockgas/particles/cluster_finder.hpp"
#include "shockgas/particles/simulate.hpp"

namespace shockgas::particles {
namespace {

struct Case {
  double r;
  ParticleSolver solver;
};

RunResult run(const Case& c, ClusterRecord record, std::size_t N = 2000) {
  InitialParams ip;
  ip.N = N;
  ip.seed = 5;
  ParticleParams p;
  p.r = c.r;
  p.solver = c.solver;
  p.t_end = 300;
  p.samples = 3;
  p.final_clusters = record;
  const InitialCondition ic(ip);
  return simulate(ic.realization(0), ic.length(), p);
}

TEST(FinalClusters, AreTheHeavyClustersOfTheFinalState) {
  for (const Case c : {Case{0.0, ParticleSolver::hull}, Case{0.0, ParticleSolver::events},
                       Case{0.5, ParticleSolver::events}}) {
    const RunResult r = run(c, ClusterRecord::automatic);
    ASSERT_TRUE(r.final_clusters.has_value()) << c.r;
    const double L = 2000;  // ring_length(0, N): mean spacing 1
    const ClusterCriteria criteria =
        c.r == 0 ? merged_bodies_criteria() : default_cluster_criteria(0.01, 1.0, r.stop.time);
    std::vector<Cluster> expected;
    for (const Cluster& k : find_clusters(r.final_state, L, criteria))
      if (k.m > 1.5) expected.push_back(k);
    std::sort(expected.begin(), expected.end(), [](const Cluster& a, const Cluster& b) { return a.x < b.x; });
    const Bodies& got = *r.final_clusters;
    ASSERT_EQ(got.size(), expected.size()) << c.r;
    ASSERT_GT(got.size(), 10u);  // a gas at t = 300 holds about 1.9 N t^(-2/3) = 85 shocks
    for (std::size_t i = 0; i < got.size(); ++i) {
      EXPECT_EQ(got.x[i], expected[i].x);
      EXPECT_EQ(got.v[i], expected[i].v);
      EXPECT_EQ(got.m[i], expected[i].m);
    }
  }
}

TEST(FinalClusters, AreRecordedAsTheKeySays) {
  const Case hull{0.0, ParticleSolver::hull};
  EXPECT_FALSE(run(hull, ClusterRecord::never).final_clusters.has_value());
  EXPECT_TRUE(run(hull, ClusterRecord::always).final_clusters.has_value());
  // auto: while 12 bytes per particle and realization stay within 1 GB ...
  ParticleParams p;
  p.realizations = 100;
  EXPECT_TRUE(records_final_clusters(p, 833333));
  EXPECT_FALSE(records_final_clusters(p, 833334));
  p.final_clusters = ClusterRecord::always;
  EXPECT_TRUE(records_final_clusters(p, 833334));
  // ... and one realization has at most 10^6 particles.
  p.final_clusters = ClusterRecord::automatic;
  p.realizations = 1;
  EXPECT_TRUE(records_final_clusters(p, 1000000));
  EXPECT_FALSE(records_final_clusters(p, 1000001));
  p.final_clusters = ClusterRecord::always;
  EXPECT_TRUE(records_final_clusters(p, 10000000));
}

}  // namespace
}  // namespace shockgas::particles
