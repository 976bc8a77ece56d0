// Long checks of the particle engine (label `slow`): the full sizes.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "hull_agreement.hpp"
#include "shockgas/core/initial_condition.hpp"
#include "shockgas/particles/simulate.hpp"

namespace shockgas::particles {
namespace {

const std::vector<double> kTimes = {1.0, 10.0, 100.0, 1000.0, 10000.0};

TEST(HullAgreementSlow, LatticeLine) {
  testing::expect_engine_matches_hull(100000, "lattice", "line", kTimes, 1);
}
TEST(HullAgreementSlow, RandomLine) {
  testing::expect_engine_matches_hull(100000, "random", "line", kTimes, 2);
}
TEST(HullAgreementSlow, LatticeRing) {
  testing::expect_engine_matches_hull(100000, "lattice", "ring", kTimes, 3);
}
TEST(HullAgreementSlow, RandomRing) {
  testing::expect_engine_matches_hull(100000, "random", "ring", kTimes, 4);
}

TEST(ConservationSlow, MomentumOverTenMillionCollisions) {
  InitialParams ip;
  ip.N = 100000;
  ip.seed = 8;
  const Bodies b = make_initial_bodies(ip);
  ParticleParams p;
  p.t_end = 1e9;
  p.samples = 1;
  p.clusters = false;
  p.max_collisions = 10'000'000;
  const RunResult out = simulate(b, 1e5, p);
  ASSERT_GE(out.collisions, 10'000'000u);
  // One rounding of O(1) velocities per collision (~1e-16): a random walk over
  // 1e7 collisions gives ~3e-13; 1e-9 would catch any systematic error.
  EXPECT_NEAR(total_momentum(out.final_state), total_momentum(b), 1e-9);
}

// The paper's Fig. 2 (small) at delta = 10^-3: N = 10^4, r = 0.9 to t = 10^4,
// realization 0 of seed 1999. Dense clusters there collide hundreds of times within
// 1e-12 t (sticky: from t ~ 5600, 7.3e5 collisions; elastic: 9.2e7 collisions), once
// stopped as a false collapse. A threshold forbids collapse: the run must complete.
void expect_fig2_threshold_completes(const std::string& subthreshold) {
  InitialParams ip;
  ip.N = 10000;
  ip.seed = 1999;
  ParticleParams p;
  p.r = 0.9;
  p.delta = 1e-3;
  p.subthreshold = parse_enum<Subthreshold>(subthreshold, "particles.subthreshold");
  p.t_end = 1e4;
  p.samples = 10;
  p.clusters = false;
  const Bodies b = make_initial_bodies(ip, 0);
  const RunResult out = simulate(b, 1e4, p);
  EXPECT_EQ(out.stop.reason, StopReason::completed);
  EXPECT_EQ(out.stop.time, 1e4);
  // Momentum random walk of roundings (~1e-16 per collision, <= 10^8 collisions): ~1e-12.
  EXPECT_NEAR(total_momentum(out.final_state), total_momentum(b), 1e-9);
}

TEST(ThresholdSlow, Fig2StickyDoesNotFalselyCollapse) { expect_fig2_threshold_completes("sticky"); }
TEST(ThresholdSlow, Fig2ElasticDoesNotFalselyCollapse) { expect_fig2_threshold_completes("elastic"); }

// Least-squares slope of log T against log t over t in [t0, t1].
double temperature_exponent(const TimeSeries& s, double t0, double t1) {
  double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t k = 0; k < s.size(); ++k) {
    if (s.t[k] < t0 || s.t[k] > t1) continue;
    const double x = std::log(s.t[k]), y = std::log(s.T[k]);
    n += 1, sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

// Sticky-gas regime eps^(-3/2) << t << N^(3/2) (eps = (1 - r)/2, docs/design.md §1):
// T ~ t^(-2/3) whatever r. N = 10^5, one realization; window [100, 3000]
// (t_stick = 8 for r = 0.5). Measured slopes: -0.666 (r = 0.5), -0.668 (r = 0).
void expect_sticky_exponent(double r) {
  InitialParams ip;
  ip.N = 100000;
  ip.seed = 3;
  ParticleParams p;
  p.r = r;
  p.delta = 1e-2;
  p.t_end = 3000;
  p.samples = 41;
  p.clusters = false;
  const RunResult out = simulate(make_initial_bodies(ip), 1e5, p);
  ASSERT_EQ(out.stop.reason, StopReason::completed);
  EXPECT_NEAR(temperature_exponent(out.series, 100, 3000), -2.0 / 3.0,
              0.03);  // the stated tolerance on the exponent
}

TEST(CoolingSlow, LateTimeExponentHalfRestitution) { expect_sticky_exponent(0.5); }
TEST(CoolingSlow, LateTimeExponentSticky) { expect_sticky_exponent(0.0); }

}  // namespace
}  // namespace shockgas::particles
