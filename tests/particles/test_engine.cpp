// The event-driven engine on small systems with hand-computed outcomes, and
// conservation laws on larger ones.
#include <gtest/gtest.h>

#include <cmath>

#include "shockgas/core/error.hpp"
#include "shockgas/core/initial_condition.hpp"
#include "shockgas/particles/simulate.hpp"

namespace shockgas::particles {
namespace {

ParticleParams line_params(double r, double delta, double t_end) {
  ParticleParams p;
  p.r = r;
  p.delta = delta;
  p.geometry = Geometry::line;
  p.t_end = t_end;
  p.samples = 1;
  p.clusters = false;
  return p;
}

Bodies bodies(std::initializer_list<double> x, std::initializer_list<double> v) {
  Bodies b;
  b.x = x;
  b.v = v;
  b.m.assign(b.x.size(), 1.0);
  return b;
}

TEST(Engine, TwoBodiesHeadOn) {
  // x = 0, 1; v = 1, -1: contact at t = 1/2, x = 1/2; r = 1/2: v' = -1/2, u' = 1/2.
  // At t = 1.5 they are at 1/2 -+ 1/2.
  const RunResult out = simulate(bodies({0.0, 1.0}, {1.0, -1.0}), 10.0, line_params(0.5, 0.0, 1.5));
  ASSERT_EQ(out.collisions, 1u);
  EXPECT_EQ(out.series.inelastic.back(), 1.0);
  const double tol = 1e-15;  // a few roundings of O(1) values
  EXPECT_NEAR(out.final_state.x[0], 0.0, tol);
  EXPECT_NEAR(out.final_state.x[1], 1.0, tol);
  EXPECT_NEAR(out.final_state.v[0], -0.5, tol);
  EXPECT_NEAR(out.final_state.v[1], 0.5, tol);
  EXPECT_NEAR(out.series.dissipated.back(), 0.25 * 0.75 * 4, tol);  // (1 - r^2) g^2 / 4 m
}

TEST(Engine, ThreeBodiesSequence) {
  // x = 0, 1, 3; v = 1, 0, -1; r = 1 (elastic, equal masses: exchange).
  // t = 1: bodies 0,1 meet at x = 1 -> v = 0, 1. Body 1 (v = 1) meets body 2
  // (x = 3 - t) at 1 + s = 2 - s, s = 1/2: t = 1.5, x = 1.5 -> v = -1, 1.
  // Body 1 (v = -1) meets body 0 (v = 0, at x = 1) at t = 2, x = 1 -> exchange.
  // Final v = -1, 0, 1 at t = 4: body 0 at 1 - 2 = -1, body 1 at 1, body 2 at 1.5 + 2.5 = 4.
  ParticleParams p = line_params(1.0, 0.0, 4.0);
  const RunResult out = simulate(bodies({0.0, 1.0, 3.0}, {1.0, 0.0, -1.0}), 10.0, p);
  ASSERT_EQ(out.collisions, 3u);
  const double tol = 1e-14;  // rounding of a few O(1) operations
  EXPECT_NEAR(out.final_state.x[0], -1.0, tol);
  EXPECT_NEAR(out.final_state.x[1], 1.0, tol);
  EXPECT_NEAR(out.final_state.x[2], 4.0, tol);
  EXPECT_NEAR(out.final_state.v[0], -1.0, tol);
  EXPECT_NEAR(out.final_state.v[2], 1.0, tol);
  EXPECT_NEAR(out.series.dissipated.back(), 0.0, tol);
}

TEST(Engine, MergeThenUnequalMassCollision) {
  // r = 0: bodies 0 (x 0, v 2) and 1 (x 1, v 0) merge at t = 1/2, x = 1 -> mass 2, v = 1.
  // The pair meets body 2 (x 3, v -1) when 1 + (t - 1/2) = 3 - t: t = 1.25, x = 1.75,
  // merging into mass 3 at v = (2 - 1) / 3 = 1/3. At t = 2.25: x = 1.75 + 1/3.
  ParticleParams p = line_params(0.0, 0.0, 2.25);
  const RunResult out = simulate(bodies({0.0, 1.0, 3.0}, {2.0, 0.0, -1.0}), 10.0, p);
  ASSERT_EQ(out.final_state.size(), 1u);
  EXPECT_EQ(out.series.merges.back(), 2.0);
  const double tol = 1e-14;  // rounding of a few O(1) operations
  EXPECT_NEAR(out.final_state.m[0], 3.0, tol);
  EXPECT_NEAR(out.final_state.v[0], 1.0 / 3.0, tol);
  EXPECT_NEAR(out.final_state.x[0], 1.75 + 1.0 / 3.0, tol);
  // Energy: 2 + 0.5 before, 3 / 18 after.
  EXPECT_NEAR(out.series.dissipated.back(), 2.5 - 1.0 / 6.0, tol);
}

TEST(Engine, UnequalMassesBounce) {
  // m = 1 at x = 0 (v = 2), m = 3 at x = 1 (v = 0), r = 1/2: contact at t = 1/2, x = 1;
  // v' = 2 - 1.5 * 3/4 * 2 = -1/4, u' = 1.5 * 1/4 * 2 = 3/4. At t = 2.5: x = 1 - 1/2, 1 + 3/2.
  Bodies b = bodies({0.0, 1.0}, {2.0, 0.0});
  b.m = {1.0, 3.0};
  const RunResult out = simulate(b, 10.0, line_params(0.5, 0.0, 2.5));
  ASSERT_EQ(out.collisions, 1u);
  const double tol = 1e-15;  // a few roundings of O(1) values
  EXPECT_NEAR(out.final_state.v[0], -0.25, tol);
  EXPECT_NEAR(out.final_state.v[1], 0.75, tol);
  EXPECT_NEAR(out.final_state.x[0], 0.5, tol);
  EXPECT_NEAR(out.final_state.x[1], 2.5, tol);
  EXPECT_NEAR(out.series.dissipated.back(), 2.0 - 0.875, tol);  // 2 before, 0.875 after
}

TEST(Engine, StickySubthresholdMerges) {
  // g = 0.05 < delta = 0.1 with sticky sub-threshold: merge; r is irrelevant.
  ParticleParams p = line_params(0.9, 0.1, 100.0);
  p.subthreshold = Subthreshold::sticky;
  const RunResult out = simulate(bodies({0.0, 1.0}, {0.05, 0.0}), 10.0, p);
  ASSERT_EQ(out.final_state.size(), 1u);
  EXPECT_NEAR(out.final_state.v[0], 0.025, 1e-17);  // one rounding
}

TEST(Engine, RingWrapsAcrossTheOrigin) {
  // Ring L = 4: x = 0.5 (v = -1) and 3.5 (v = 0) meet across 0 at t = 1, x = -0.5 = 3.5.
  // r = 1: exchange. At t = 2: the first body stays at 3.5, the second at 3.5 - 1 = 2.5.
  ParticleParams p = line_params(1.0, 0.0, 2.0);
  p.geometry = Geometry::ring;
  const RunResult out = simulate(bodies({0.5, 3.5}, {-1.0, 0.0}), 4.0, p);
  ASSERT_EQ(out.collisions, 1u);
  const double tol = 1e-15;  // rounding of O(1) values
  EXPECT_NEAR(out.final_state.x[0], 2.5, tol);
  EXPECT_NEAR(out.final_state.v[0], -1.0, tol);
  EXPECT_NEAR(out.final_state.x[1], 3.5, tol);
  EXPECT_NEAR(out.final_state.v[1], 0.0, tol);
}

ParticleParams ring_params(double r, double delta, double t_end) {
  ParticleParams p = line_params(r, delta, t_end);
  p.geometry = Geometry::ring;
  p.samples = 20;
  return p;
}

InitialParams lattice(std::size_t n, std::uint64_t seed) {
  InitialParams ip;
  ip.N = n;
  ip.seed = seed;
  return ip;
}

TEST(Engine, MomentumKeptOverAMillionCollisions) {
  const Bodies b = make_initial_bodies(lattice(10000, 3));
  ParticleParams p = ring_params(0.9, 1e-2, 1e9);
  p.max_collisions = 1000000;
  const RunResult out = simulate(b, 1e4, p);
  EXPECT_EQ(out.stop.reason, StopReason::event_limit);
  ASSERT_GE(out.collisions, 1000000u);
  // Each collision changes the momentum by one rounding of an O(1) velocity (~1e-16);
  // a random walk over 1e6 collisions gives ~1e-13, a systematic drift 1e-10.
  EXPECT_NEAR(total_momentum(out.final_state), total_momentum(b), 1e-10);
}

TEST(Engine, ElasticGasKeepsEnergy) {
  const Bodies b = make_initial_bodies(lattice(2000, 4));
  const RunResult out = simulate(b, 2000.0, ring_params(1.0, 0.0, 100.0));
  ASSERT_GT(out.collisions, 50000u);
  // Rounding per collision ~1e-16 relative; 1e5 collisions: well below 1e-11.
  EXPECT_NEAR(kinetic_energy(out.final_state), kinetic_energy(b), 1e-11 * kinetic_energy(b));
  EXPECT_EQ(out.series.dissipated.back(), 0.0);
}

TEST(Engine, EnergyBalanceWithDissipation) {
  const Bodies b = make_initial_bodies(lattice(2000, 5));
  const RunResult out = simulate(b, 2000.0, ring_params(0.5, 1e-3, 100.0));
  // Energy lost = energy dissipated by the collision rule, up to rounding (~1e-16 per collision).
  EXPECT_NEAR(kinetic_energy(out.final_state) + out.series.dissipated.back(), kinetic_energy(b),
              1e-11 * kinetic_energy(b));
  EXPECT_GT(out.series.elastic.back(), 0.0);
  EXPECT_GT(out.series.inelastic.back(), 0.0);
  EXPECT_EQ(out.series.collisions.back(), out.series.elastic.back() + out.series.inelastic.back());
}

TEST(Engine, OrderIsKeptAndFinalStateWrapped) {
  const double L = 1000.0;
  const Bodies b = make_initial_bodies(lattice(1000, 6));
  const RunResult out = simulate(b, L, ring_params(0.9, 1e-2, 500.0));
  ASSERT_EQ(out.final_state.size(), 1000u);
  for (std::size_t i = 0; i < 1000; ++i) {
    EXPECT_GE(out.final_state.x[i], 0.0);
    EXPECT_LT(out.final_state.x[i], L);
    if (i > 0) {
      EXPECT_LE(out.final_state.x[i - 1], out.final_state.x[i]);
    }
  }
}

// L = 0 means N, as initial.L does in a scene and in the Python module
// (ring_length): the same run as L = N, to the bit, and a negative L refused.
TEST(Engine, RingLengthZeroMeansTheNumberOfBodies) {
  InitialParams ip;
  ip.N = 500;
  ip.seed = 11;
  const Bodies initial = make_initial_bodies(ip);
  ParticleParams p;
  p.r = 0.5;
  p.t_end = 20.0;
  p.samples = 3;
  const RunResult zero = simulate(initial, 0.0, p), n = simulate(initial, 500.0, p);
  EXPECT_EQ(zero.collisions, n.collisions);
  EXPECT_EQ(zero.final_state.x, n.final_state.x);
  EXPECT_EQ(zero.final_state.v, n.final_state.v);
  EXPECT_THROW(simulate(initial, -1.0, p), InputError);
}

}  // namespace
}  // namespace shockgas::particles
