// The inelastic gas of data/scenes/default.toml (r = 0.5, delta = 10^-2, 2 10^4
// particles to t = 10^4) counts in time the shocks of Burgers turbulence that
// hold two or more particles once its clusters have gathered the sticky gas's
// mass (cluster_count_law.hpp).
#include <gtest/gtest.h>

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
TEST(ClusterCountLaw, DefaultSceneCountsTheShocksOfTwoOrMoreParticlesAtItsEnd) {
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

}  // namespace
}  // namespace shockgas::compare
