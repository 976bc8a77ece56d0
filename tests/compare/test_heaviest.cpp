// The heaviest shock and cluster (heaviest.hpp): a Burgers shock and a sticky
// cluster from the same Riemann data, together for a uniform density, apart for
// a non-uniform one.
#include <gtest/gtest.h>

#include "shockgas/compare/heaviest.hpp"
#include "shockgas/continuum/solve.hpp"
#include "shockgas/core/sticky_hull.hpp"

namespace shockgas::compare {
namespace {

// v = 1 then -1 across x = 1/2 (a shock; a fan across x = 0), density rho_left then 1.
InitialField riemann(double rho_left) {
  InitialField f;
  f.length = 1.0;
  f.v0 = [](double x) { return x < 0.5 ? 1.0 : -1.0; };
  f.rho0 = [rho_left](double x) { return x < 0.5 ? rho_left : 1.0; };
  return f;
}

// The same data as N sticky point masses on a lattice, at time t (the exact sticky gas).
Bodies sticky_state(double rho_left, std::size_t N, double t) {
  Bodies b;
  for (std::size_t i = 0; i < N; ++i) {
    const double x = (i + 0.5) / N;
    b.push_back(x, x < 0.5 ? 1.0 : -1.0, (x < 0.5 ? rho_left : 1.0) / N);
  }
  return to_bodies(sticky_clusters_ring(b, 1.0, t));
}

continuum::ContinuumResult exact(double rho_left, double t) {
  continuum::ContinuumParams p;
  p.cells = 1000;
  return continuum::solve("hopf_lax", riemann(rho_left), p, t);
}

TEST(Heaviest, BurgersShockStaysWhereTheMeanVelocitySaysWhateverTheDensity) {
  // s = (1 + (-1)) / 2 = 0; the shock swallows rho_L (v_L - s) t + rho_R (s - v_R) t.
  for (double rho_left : {1.0, 4.0}) {
    const auto s = heaviest_shock(exact(rho_left, 0.3));
    ASSERT_TRUE(s);
    EXPECT_NEAR(s->x, 0.5, 1e-12);
    EXPECT_NEAR(s->mass, (rho_left + 1) * 0.3, 1e-12);
  }
}

TEST(Heaviest, StickyClusterMovesWithItsMomentum) {
  // Pressureless delta-shock: speed (sqrt(rho_L) v_L + sqrt(rho_R) v_R) / (sqrt(rho_L) + sqrt(rho_R)),
  // 0 for rho_L = 1 and 1/3 for rho_L = 4; mass 4 t at rho_L = 4 (heaviest.hpp). N point
  // masses resolve the swallowed interval to one spacing 1/N.
  const std::size_t N = 4000;
  const particles::ClusterCriteria none = particles::merged_bodies_criteria();
  const auto uniform = heaviest_cluster(sticky_state(1.0, N, 0.3), 1.0, none);
  ASSERT_TRUE(uniform);
  EXPECT_NEAR(uniform->x, 0.5, 1.0 / N);
  EXPECT_NEAR(uniform->v, 0.0, 1e-12);
  const auto dense = heaviest_cluster(sticky_state(4.0, N, 0.3), 1.0, none);
  ASSERT_TRUE(dense);
  EXPECT_NEAR(dense->v, 1.0 / 3.0, 4.0 / N);
  EXPECT_NEAR(dense->x, 0.5 + 0.3 / 3.0, 4.0 / N);
  EXPECT_NEAR(dense->m, 4 * 0.3, 4.0 / N);
  // ... where the Burgers shock of the same data has not moved: they part by t/3
  EXPECT_NEAR(dense->x - heaviest_shock(exact(4.0, 0.3))->x, 0.1, 4.0 / N);
}

TEST(Heaviest, NothingWithoutMass) {
  EXPECT_FALSE(heaviest_cluster(Bodies{}, 1.0, {}));
  continuum::ContinuumParams p;
  p.cells = 200;
  p.nu = 1e-2;
  // Hopf-Cole gives v only: its shocks hold no mass
  EXPECT_FALSE(heaviest_shock(continuum::solve("hopf_cole", riemann(1.0), p, 0.3)));
}

}  // namespace
}  // namespace shockgas::compare
