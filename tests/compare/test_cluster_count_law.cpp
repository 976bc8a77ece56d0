// The sticky gas (r = 0, the exact hull) counts in time the shocks of Burgers
// turbulence that hold two or more particles: its clusters are the shocks
// (cluster_count_law.hpp).
#include <gtest/gtest.h>

#include "cluster_count_law.hpp"

namespace shockgas::compare {
namespace {

using namespace testing;

// 10 realizations of 10^5 particles to t = 10^4 (samples at 1, 10, ..., 10^4):
// from t = 10^3 on the mean count lies within 3 standard errors of the exact
// count of shocks heavier than 1.5 particles (measured: within 1.1). Three
// standard errors of a 10-realization mean: a two-sided Student t of 9
// degrees of freedom exceeds 3 with probability 1.5 %. At t = 10^3 the count
// lies below C t^(-2/3) by more than 3 of them (measured: 24): the shocks
// lighter than a particle are not clusters.
TEST(ClusterCountLaw, StickyGasCountsTheShocksOfTwoOrMoreParticles) {
  const InitialParams ip = white_noise(100000);
  particles::ParticleParams p;
  p.r = 0.0;
  p.delta = 0.0;
  p.solver = particles::ParticleSolver::hull;
  p.t_end = 1e4;
  p.samples = 5;
  p.realizations = 10;
  const particles::EnsembleResult e = particles::run_ensemble(ip, p);
  const WhiteNoiseReferences w = *white_noise_references(ip);
  ASSERT_EQ(e.t.size(), 5u);
  EXPECT_EQ(expect_counts_the_shocks(e, w, 1e3, 3.0), 2u);
  const std::size_t at_1e3 = 3;
  ASSERT_NEAR(e.t[at_1e3], 1e3, 1e-9);
  EXPECT_GT(all_shocks(w, e.t[at_1e3]) - e.n_clusters.mean[at_1e3], 3 * e.n_clusters.stderr_[at_1e3]);
}

}  // namespace
}  // namespace shockgas::compare
