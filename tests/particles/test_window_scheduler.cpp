// Time windows over domains (shockgas/particles/window_scheduler.hpp) against the global
// event queue: the same collisions, so the same final state to the last bit.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include "shockgas/core/error.hpp"
#include "shockgas/core/initial_condition.hpp"
#include "shockgas/particles/simulate.hpp"

namespace shockgas::particles {
namespace {

struct Case {
  std::size_t N;
  std::string positions, velocities, geometry;
  double r, delta, t_end;
};

Bodies start(const Case& c) {
  InitialParams ip;
  ip.N = c.N;
  ip.positions = parse_enum<Positions>(c.positions, "initial.positions");
  ip.velocities = parse_enum<Velocities>(c.velocities, "initial.velocities");
  ip.seed = 77;
  return make_initial_bodies(ip);
}

ParticleParams params(const Case& c, const std::string& schedule) {
  ParticleParams p;
  p.r = c.r;
  p.delta = c.delta;
  p.geometry = parse_enum<Geometry>(c.geometry, "particles.geometry");
  p.t_end = c.t_end;
  p.samples = 12;  // every sample time ends a window
  p.clusters = false;
  p.schedule = parse_enum<Schedule>(schedule, "particles.schedule");
  return p;
}

void expect_same_run(const Case& c) {
  const Bodies b = start(c);
  const double L = static_cast<double>(c.N);
  const RunResult global = simulate(b, L, params(c, "global"));
  const RunResult windows = simulate(b, L, params(c, "windows"));
  ASSERT_EQ(global.stop.reason, StopReason::completed);
  ASSERT_EQ(windows.stop.reason, StopReason::completed);
  ASSERT_GT(global.collisions, 10 * c.N);  // long enough for many windows
  EXPECT_EQ(windows.collisions, global.collisions);
  EXPECT_EQ(windows.series.elastic, global.series.elastic);
  // T on the windows is summed per domain and combined in domain order: the same
  // sums in another order, equal to 2 (N + 4) eps relative (Higham, 4.2).
  ASSERT_EQ(windows.series.T.size(), global.series.T.size());
  const double rounding = 2 * (static_cast<double>(c.N) + 4) * std::numeric_limits<double>::epsilon();
  for (std::size_t k = 0; k < global.series.T.size(); ++k)
    EXPECT_NEAR(windows.series.T[k], global.series.T[k], rounding * global.series.T[k]) << "sample " << k;
  ASSERT_EQ(windows.final_state.size(), global.final_state.size());
  std::size_t differ = 0;
  for (std::size_t i = 0; i < global.final_state.size(); ++i)
    differ += windows.final_state.x[i] != global.final_state.x[i] ||
              windows.final_state.v[i] != global.final_state.v[i];
  EXPECT_EQ(differ, 0u) << "bodies whose x or v differ in any bit";
  // The energy lost is summed in another order: equal to rounding of the sum.
  const double lost = global.series.dissipated.back();
  EXPECT_NEAR(windows.series.dissipated.back(), lost, 1e-12 * lost);
}

// Bodies b from scratch on both schedules: at least `min_collisions`, and the
// same collisions and final state to the bit.
void expect_same_final_state(const Bodies& b, const Case& c, std::uint64_t min_collisions) {
  const double L = static_cast<double>(c.N);
  const RunResult global = simulate(b, L, params(c, "global"));
  const RunResult windows = simulate(b, L, params(c, "windows"));
  ASSERT_GT(global.collisions, min_collisions);
  EXPECT_EQ(windows.collisions, global.collisions);
  EXPECT_EQ(windows.final_state.x, global.final_state.x);
  EXPECT_EQ(windows.final_state.v, global.final_state.v);
}

TEST(WindowScheduler, SameCollisionsAsTheGlobalQueueOnARing) {
  expect_same_run({20000, "random", "uniform", "ring", 0.9, 1e-2, 300.0});
}

TEST(WindowScheduler, SameCollisionsOnALatticeWithGaussianVelocities) {
  expect_same_run({12000, "lattice", "gaussian", "ring", 0.5, 1e-2, 300.0});
}

TEST(WindowScheduler, SameCollisionsOnALineElastic) {
  expect_same_run({8000, "random", "uniform", "line", 1.0, 0.0, 100.0});
}

TEST(WindowScheduler, FastBodiesDoNotCrossTheCuts) {
  // Two pistons of bodies 20 times faster than the rest drive shocks through the
  // gas: a cut chosen among slow bodies must still hold when a shock arrives, or
  // the collisions would differ from the global queue's.
  Case c{8000, "random", "uniform", "ring", 0.9, 1e-2, 6.0};
  Bodies b = start(c);
  for (std::size_t i = 1550; i < 1700; ++i) b.v[i] = 20.0;   // toward the cut near body 2000
  for (std::size_t i = 6300; i < 6450; ++i) b.v[i] = -20.0;  // toward the cut near body 6000
  expect_same_final_state(b, c, 10 * c.N);
}

TEST(WindowScheduler, FastElasticBodiesCrossingTheGasDoNotCrossTheCuts) {
  // r = 1: a fast velocity passes from body to body (equal masses exchange
  // velocities) and crosses the gas at 20 times the thermal speed with few
  // collisions. The cuts' bounds must see it coming from far away.
  Case c{8000, "random", "uniform", "ring", 1.0, 0.0, 50.0};
  Bodies b = start(c);
  for (std::size_t i = 300; i < b.size(); i += 400) b.v[i] = i % 800 == 300 ? 20.0 : -20.0;
  expect_same_final_state(b, c, 10 * c.N);
}

TEST(WindowScheduler, FallsBackToTheGlobalQueueWhenNoCutCanOpen) {
  // Every body at the same point: every gap is 0, no window can advance, and the
  // run continues on the global queue with the same result.
  Bodies b = start({2048, "random", "uniform", "line", 0.9, 1e-2, 1.0});
  for (double& x : b.x) x = 100.0;
  expect_same_final_state(b, {2048, "", "", "line", 0.9, 1e-2, 20.0}, 2048);
}

TEST(WindowScheduler, APlanEndsNearTheCollisionLimit) {
  // A plan of a small system may hold up to 2^24 collisions (84 per body here),
  // but no more than the limit leaves it, and at least N at the last plan's
  // rate: the run stops within N collisions of the limit plus the rate's change
  // over one plan, deep into the run as early. Measured 0.88-0.96 N over; with
  // plans bounded only by the cuts and 2^24, 1.6-2.5 N.
  Case c{200000, "random", "uniform", "ring", 0.9, 1e-2, 1e6};
  for (const std::uint64_t limit : {5'000'000ull, 20'000'000ull, 40'000'000ull}) {
    ParticleParams p = params(c, "windows");
    p.max_collisions = limit;
    const RunResult out = simulate(start(c), 1e6, p);
    EXPECT_EQ(out.stop.reason, StopReason::event_limit);
    EXPECT_GE(out.collisions, limit);
    EXPECT_LE(out.collisions, limit + 2 * c.N) << "limit " << limit;
  }
}

TEST(WindowScheduler, HaltsOnlyBetweenWindowsWithMomentumKept) {
  // A collision limit stops the run after the window in which it is reached: all
  // domains then stand at one time, so the state is a state of the gas.
  Case c{50000, "random", "uniform", "ring", 0.9, 1e-2, 1e6};
  const Bodies b = start(c);
  ParticleParams p = params(c, "windows");
  p.max_collisions = 100000;
  const RunResult out = simulate(b, 50000.0, p);
  EXPECT_EQ(out.stop.reason, StopReason::event_limit);
  EXPECT_GE(out.collisions, p.max_collisions);
  EXPECT_LE(out.collisions, p.max_collisions + 5 * c.N);  // a plan ends near the limit (above)
  double p0 = 0, p1 = 0;
  for (double v : b.v) p0 += v;
  for (double v : out.final_state.v) p1 += v;
  EXPECT_NEAR(p1, p0, 1e-9 * c.N);  // rounding of ~10^5 collisions
  for (std::size_t i = 1; i < out.final_state.size(); ++i)
    ASSERT_LE(out.final_state.x[i - 1], out.final_state.x[i]) << "bodies out of order at " << i;
}

TEST(WindowScheduler, RefusedWhereItIsNotExact) {
  Case c{4096, "random", "uniform", "ring", 0.5, 1e-2, 10.0};
  const Bodies b = start(c);
  ParticleParams sticky = params(c, "windows");
  sticky.subthreshold = Subthreshold::sticky;  // merged bodies of unequal mass bounce with r > 0
  EXPECT_THROW(simulate(b, 4096.0, sticky), InputError);
  c.delta = 0.0;  // inelastic collapse possible
  EXPECT_THROW(simulate(b, 4096.0, params(c, "windows")), InputError);
  // A schedule is named through its declaration (shockgas/particles/params.cpp): an unknown name is refused
  // there.
  ParticleParams p = params({4096, "lattice", "uniform", "ring", 0.9, 1e-2, 10.0}, "auto");
  EXPECT_THROW(parameters().set(p, "schedule", ParameterValue::of("sometimes")), InputError);
}

}  // namespace
}  // namespace shockgas::particles
