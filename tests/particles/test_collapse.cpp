// Inelastic collapse with delta = 0: three particles on a line collapse for
// r < 7 - 4 sqrt(3) ~ 0.0718 and not above (McNamara & Young, Phys. Fluids A 4,
// 496 (1992)); the engine must stop cleanly, keeping what it observed.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "shockgas/core/initial_condition.hpp"
#include "shockgas/particles/simulate.hpp"

namespace shockgas::particles {
namespace {

// The middle particle at rest between two approaching ones (not symmetric, so
// that the collisions alternate 1-2, 2-3, 1-2, ...).
RunResult three_on_a_line(double r) {
  Bodies b;
  b.x = {0.0, 1.0, 2.5};
  b.v = {1.0, 0.0, -1.0};
  b.m = {1.0, 1.0, 1.0};
  ParticleParams p;
  p.r = r;
  p.delta = 0.0;
  p.geometry = Geometry::line;
  p.t_end = 100.0;
  p.samples = 10;
  p.clusters = false;
  return simulate(b, 10.0, p);
}

TEST(Collapse, ThreeParticlesBelowThresholdCollapse) {
  for (double r : {0.01, 0.05, 0.07}) {  // r_c = 7 - 4 sqrt(3) = 0.0718
    SCOPED_TRACE(r);
    const RunResult out = three_on_a_line(r);
    EXPECT_EQ(out.stop.reason, StopReason::collapse);
    // The outer particles meet the middle one between t = 1 and t = 1.5 + the bouncing time.
    EXPECT_GT(out.stop.time, 1.0);
    EXPECT_LT(out.stop.time, 5.0);
    EXPECT_GT(out.stop.position, 0.9);  // between the first contacts, x in (1, 1.75)
    EXPECT_LT(out.stop.position, 2.0);
    // Everything up to the collapse is kept: the sample at t = 1 and the final state.
    ASSERT_GE(out.series.size(), 1u);
    EXPECT_LE(out.series.t.back(), out.stop.time);
    ASSERT_EQ(out.final_state.size(), 3u);
    // At the collapse all three are at one point with one velocity (the centre of mass's, 0).
    const double tol = 1e-6;  // the collapse is detected once time stops advancing (< 1e-10)
    EXPECT_NEAR(out.final_state.x[0], out.final_state.x[2], tol);
    EXPECT_NEAR(out.final_state.v[0], out.final_state.v[2], tol);
    EXPECT_NEAR(total_momentum(out.final_state), 0.0, 1e-14);  // rounding of O(1) momenta
  }
}

TEST(Collapse, ThreeParticlesAboveThresholdEscape) {
  for (double r : {0.075, 0.1, 0.5}) {
    SCOPED_TRACE(r);
    const RunResult out = three_on_a_line(r);
    EXPECT_EQ(out.stop.reason, StopReason::completed);
    EXPECT_EQ(out.stop.time, 100.0);
    EXPECT_EQ(out.series.size(), 10u);
    // Finitely many collisions: the sequence ends and the three separate.
    EXPECT_LT(out.collisions, 10000u);
    EXPECT_LT(out.final_state.v[0], out.final_state.v[1]);
    EXPECT_LT(out.final_state.v[1], out.final_state.v[2]);
  }
}

TEST(Collapse, LargeRingStopsWithoutHanging) {
  InitialParams ip;
  ip.N = 2000;
  ip.seed = 11;
  ParticleParams p;
  p.r = 0.5;
  p.delta = 0.0;
  p.t_end = 1e4;
  p.clusters = false;
  const RunResult out = simulate(make_initial_bodies(ip), 2000.0, p);
  EXPECT_EQ(out.stop.reason, StopReason::collapse);
  EXPECT_GE(out.stop.position, 0.0);
  EXPECT_LT(out.stop.position, 2000.0);
  EXPECT_LT(out.stop.time, 1e4);
  EXPECT_EQ(out.final_state.size(), 2000u);
}

// With a threshold there is no collapse, yet a dense cluster squeezes its gaps to
// rounding level and then collides hundreds of times within 1e-12 t. Here 40
// bodies aimed at one point (x_k = -v_k T0, v_k = 0.5 - 0.03 k) meet there at
// t = T0 = 10^4 with approach speeds 0.03 > delta: positions ~10^4 carry rounding
// ~2e-12, so the contacts resolve in a burst of ~10^3 collisions each advancing
// time by ~1e-11 < 1e-12 T0. This used to be reported as a collapse.
RunResult focused_cluster(const std::string& subthreshold) {
  const double T0 = 1e4;
  Bodies b;
  for (int k = 0; k < 40; ++k) {
    const double v = 0.5 - 0.03 * k;
    b.push_back(-v * T0, v, 1.0);
  }
  ParticleParams p;
  p.r = 0.9;
  p.delta = 1e-3;
  p.subthreshold = parse_enum<Subthreshold>(subthreshold, "particles.subthreshold");
  p.geometry = Geometry::line;
  p.t_end = 2 * T0;
  p.samples = 5;
  p.clusters = false;
  return simulate(b, 40.0, p);
}

TEST(Collapse, ThresholdResolvesADenseClusterInsteadOfCollapsing) {
  for (const char* sub : {"elastic", "sticky"}) {
    SCOPED_TRACE(sub);
    const RunResult out = focused_cluster(sub);
    EXPECT_EQ(out.stop.reason, StopReason::completed);
    EXPECT_EQ(out.stop.time, 2e4);
    // More collisions than the 256 in a row that once meant collapse: all of them
    // fall in the burst at t = 10^4 (before it the bodies fly freely).
    EXPECT_GT(out.collisions, 256u);
    // Finite, of order k^2 = 1600 for k bodies in contact (measured 902 sticky,
    // 1614 elastic); a rounding hang would run on to the 2^24 stall limit.
    EXPECT_LT(out.collisions, 10000u);
    // Momentum (initially sum v_k = 40 * 0.5 - 0.03 * 780 = -3.4) is kept to
    // rounding: ~10^3 collisions of O(1) velocities, eps = 2.2e-16 each.
    EXPECT_NEAR(total_momentum(out.final_state), -3.4, 1e-12);
    // Afterwards the bodies separate: velocities ascend along the line.
    for (std::size_t i = 1; i < out.final_state.size(); ++i)
      EXPECT_LE(out.final_state.v[i - 1], out.final_state.v[i]) << i;
  }
}

TEST(Collapse, EventLimitStopsARun) {
  InitialParams ip;
  ip.N = 1000;
  ParticleParams p;
  p.t_end = 1e6;
  p.max_collisions = 50000;
  p.clusters = false;
  const RunResult out = simulate(make_initial_bodies(ip), 1000.0, p);
  EXPECT_EQ(out.stop.reason, StopReason::event_limit);
  EXPECT_GE(out.collisions, 50000u);
  EXPECT_LT(out.collisions, 50000u + 16384u);  // checked every 2^14 collisions
}

}  // namespace
}  // namespace shockgas::particles
