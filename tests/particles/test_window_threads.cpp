// One realization on several threads (shockgas/particles/window_scheduler.hpp): the
// domains of a window run on any number of threads with the same result, to the
// last bit; and merges (r = 0) run on the windows too, with the global queue's
// result.
#include <gtest/gtest.h>

#include <limits>
#include <string>

#include "shockgas/core/initial_condition.hpp"
#include "shockgas/particles/simulate.hpp"

namespace shockgas::particles {
namespace {

struct Case {
  Geometry geometry;
  double r, delta;
  Subthreshold subthreshold;
  double t_end;
};

InitialParams gas(std::size_t n) {
  InitialParams ip;
  ip.N = n;
  ip.positions = Positions::random;
  ip.seed = 91;
  return ip;
}

// bins > 0: a histogram, so the samples sweep the whole state; 0: the domains
// measure their parts of each sample (stretch_observables.hpp).
ParticleParams params(const Case& c, std::size_t threads, std::size_t bins = 20) {
  ParticleParams p;
  p.r = c.r;
  p.delta = c.delta;
  p.subthreshold = c.subthreshold;
  p.geometry = c.geometry;
  p.t_end = c.t_end;
  p.samples = 15;  // every sample ends a sub-window
  p.histogram_bins = bins;
  p.threads = threads;
  return p;
}

// Every observable and the final state, bit for bit.
void expect_identical(const RunResult& a, const RunResult& b) {
  EXPECT_EQ(a.collisions, b.collisions);
  // The dissipated energy too: summed per domain, added in domain order.
  for (auto column :
       {&TimeSeries::t, &TimeSeries::T, &TimeSeries::mean_v, &TimeSeries::n_bodies, &TimeSeries::n_clusters,
        &TimeSeries::inelastic, &TimeSeries::elastic, &TimeSeries::merges, &TimeSeries::dissipated})
    EXPECT_EQ(a.series.*column, b.series.*column);
  EXPECT_EQ(a.histogram.density, b.histogram.density);
  for (auto column : {&Bodies::x, &Bodies::v, &Bodies::m})
    EXPECT_EQ(a.final_state.*column, b.final_state.*column);
  EXPECT_EQ(a.stop.reason, b.stop.reason);
  EXPECT_EQ(a.stop.time, b.stop.time);
}

void expect_same_on_1_2_3_threads(const Case& c) {
  const std::size_t n = 20000;
  for (std::size_t bins : {20u, 0u}) {
    SCOPED_TRACE(bins > 0 ? "samples of the whole state" : "samples in parts");
    const RunResult one = simulate(gas(n), 0, params(c, 1, bins));
    ASSERT_EQ(one.schedule.order, "windows") << one.schedule.why_global;
    ASSERT_EQ(one.stop.reason, StopReason::completed);
    ASSERT_GT(one.collisions, n / 2);  // many windows (merges: at most n - 1), and sub-windows at the samples
    for (std::size_t threads : {2u, 3u}) {
      SCOPED_TRACE(std::to_string(threads) + " threads");
      const RunResult more = simulate(gas(n), 0, params(c, threads, bins));
      EXPECT_EQ(more.schedule.threads, threads);
      EXPECT_EQ(more.schedule.order, "windows");
      expect_identical(one, more);
    }
  }
}

// The samples measured in parts by the domains against the same samples swept
// over the whole state (a histogram asks for those): the same collisions,
// counts, energy and clusters to the bit; T and the mean velocity are the same
// sums in another order, equal to 2 (N + 4) eps (Higham, Accuracy and
// Stability, 4.2), relative to T and to the velocities' scale (1).
void expect_parts_equal_whole_state(const Case& c) {
  const std::size_t n = 20000;
  const RunResult whole = simulate(gas(n), 0, params(c, 1, 20));
  const RunResult parts = simulate(gas(n), 0, params(c, 1, 0));
  ASSERT_EQ(parts.schedule.order, "windows") << parts.schedule.why_global;
  ASSERT_EQ(parts.series.size(), whole.series.size());
  for (auto column :
       {&TimeSeries::t, &TimeSeries::n_bodies, &TimeSeries::n_clusters, &TimeSeries::collisions,
        &TimeSeries::inelastic, &TimeSeries::elastic, &TimeSeries::merges, &TimeSeries::dissipated})
    EXPECT_EQ(parts.series.*column, whole.series.*column);
  const double rounding = 2 * (static_cast<double>(n) + 4) * std::numeric_limits<double>::epsilon();
  for (std::size_t k = 0; k < whole.series.size(); ++k) {
    EXPECT_NEAR(parts.series.T[k], whole.series.T[k], rounding * whole.series.T[k]) << "sample " << k;
    EXPECT_NEAR(parts.series.mean_v[k], whole.series.mean_v[k], rounding) << "sample " << k;
  }
  for (auto column : {&Bodies::x, &Bodies::v, &Bodies::m})
    EXPECT_EQ(parts.final_state.*column, whole.final_state.*column);
}

TEST(WindowThreads, RingInelasticSameOnAnyNumberOfThreads) {
  expect_same_on_1_2_3_threads({Geometry::ring, 0.9, 1e-2, Subthreshold::elastic, 200.0});
}
TEST(WindowThreads, LineInelasticSameOnAnyNumberOfThreads) {
  expect_same_on_1_2_3_threads({Geometry::line, 0.9, 1e-2, Subthreshold::elastic, 200.0});
}
TEST(WindowThreads, RingElasticSameOnAnyNumberOfThreads) {
  expect_same_on_1_2_3_threads({Geometry::ring, 1.0, 0.0, Subthreshold::elastic, 50.0});
}
TEST(WindowThreads, LineElasticSameOnAnyNumberOfThreads) {
  expect_same_on_1_2_3_threads({Geometry::line, 1.0, 0.0, Subthreshold::elastic, 50.0});
}
TEST(WindowThreads, RingStickySameOnAnyNumberOfThreads) {
  expect_same_on_1_2_3_threads({Geometry::ring, 0.0, 1e-2, Subthreshold::sticky, 300.0});
}
TEST(WindowThreads, LineStickySameOnAnyNumberOfThreads) {
  expect_same_on_1_2_3_threads({Geometry::line, 0.0, 0.0, Subthreshold::elastic, 300.0});
}

TEST(WindowThreads, SamplesInPartsEqualTheWholeStateOnARing) {
  expect_parts_equal_whole_state({Geometry::ring, 0.9, 1e-2, Subthreshold::elastic, 200.0});
}
TEST(WindowThreads, SamplesInPartsEqualTheWholeStateOnALine) {
  expect_parts_equal_whole_state({Geometry::line, 0.9, 1e-2, Subthreshold::elastic, 200.0});
}
TEST(WindowThreads, SamplesInPartsEqualTheWholeStateForStickyMerges) {
  expect_parts_equal_whole_state({Geometry::ring, 0.0, 1e-2, Subthreshold::sticky, 200.0});
}
TEST(WindowThreads, SamplesInPartsEqualTheWholeStateForElasticGas) {
  expect_parts_equal_whole_state({Geometry::line, 1.0, 0.0, Subthreshold::elastic, 50.0});
}

TEST(WindowThreads, CollisionLimitStopsAtTheSamePlaceOnAnyNumberOfThreads) {
  Case c{Geometry::ring, 0.9, 1e-2, Subthreshold::elastic, 1e6};
  ParticleParams p1 = params(c, 1), p2 = params(c, 2);
  p1.max_collisions = p2.max_collisions = 150000;
  const RunResult one = simulate(gas(20000), 0, p1);
  const RunResult two = simulate(gas(20000), 0, p2);
  ASSERT_EQ(one.stop.reason, StopReason::event_limit);
  expect_identical(one, two);
}

// Merges only: the windows against the global queue. The engine's collisions
// and final state are the same; the energy lost is summed per domain.
void expect_windows_equal_global_for_merges(Geometry geometry, double delta, Subthreshold sub) {
  Case c{geometry, 0.0, delta, sub, 300.0};
  ParticleParams windows = params(c, 2), global = params(c, 1);
  windows.schedule = Schedule::windows;
  global.schedule = Schedule::global;
  const RunResult w = simulate(gas(20000), 0, windows);
  const RunResult g = simulate(gas(20000), 0, global);
  ASSERT_EQ(w.schedule.order, "windows");
  ASSERT_GT(g.collisions, 10000u);
  EXPECT_EQ(w.collisions, g.collisions);
  EXPECT_EQ(w.series.n_bodies, g.series.n_bodies);
  EXPECT_EQ(w.final_state.x, g.final_state.x);
  EXPECT_EQ(w.final_state.v, g.final_state.v);
  EXPECT_EQ(w.final_state.m, g.final_state.m);
  const double lost = g.series.dissipated.back();
  EXPECT_NEAR(w.series.dissipated.back(), lost, 1e-12 * lost);  // another order of the same sum
}

TEST(WindowThreads, MergesOnTheWindowsEqualTheGlobalQueueOnARing) {
  expect_windows_equal_global_for_merges(Geometry::ring, 0.0, Subthreshold::elastic);
}
TEST(WindowThreads, StickyMergesOnTheWindowsEqualTheGlobalQueueOnALine) {
  expect_windows_equal_global_for_merges(Geometry::line, 1e-2, Subthreshold::sticky);
}
TEST(WindowThreads, RZeroWithAThresholdRunsOnTheWindows) {
  expect_windows_equal_global_for_merges(Geometry::ring, 1e-2, Subthreshold::elastic);  // the paper's scenes
}

TEST(WindowThreads, UnequalMassMergesOnTheWindowsEqualTheGlobalQueue) {
  // Masses rho0(x) dx: merges are mass-weighted means, convex for any masses.
  InitialParams ip;
  ip.N = 20000;
  ip.velocities = Velocities::expression;
  ip.domain = 20000.0;  // unit mean spacing
  ip.v0 = "sin(2*pi*x/20000) + 0.5*sin(2*pi*x/7) + 0.3*sin(2*pi*x/3.3)";
  ip.rho0 = "1 + 0.5*cos(2*pi*x/13)";
  const Bodies b = make_initial_bodies(ip);
  ParticleParams windows = params({Geometry::ring, 0.0, 0.0, Subthreshold::elastic, 300.0}, 2),
                 global = windows;
  windows.schedule = Schedule::windows;
  global.schedule = Schedule::global;
  const RunResult w = simulate(b, ip.domain, windows);
  const RunResult g = simulate(b, ip.domain, global);
  ASSERT_EQ(w.schedule.order, "windows") << w.schedule.why_global;
  ASSERT_GT(g.collisions, 5000u);
  EXPECT_EQ(w.collisions, g.collisions);
  for (auto column : {&Bodies::x, &Bodies::v, &Bodies::m})
    EXPECT_EQ(w.final_state.*column, g.final_state.*column);
}

TEST(WindowThreads, SummarySaysWhyWindowsDoNotApply) {
  ParticleParams p =
      params({Geometry::ring, 0.5, 1e-2, Subthreshold::sticky, 10.0}, 2);  // merges, then bounces
  const RunResult out = simulate(gas(4096), 0, p);
  EXPECT_EQ(out.schedule.order, "global");
  EXPECT_NE(out.schedule.why_global.find("unequal mass"), std::string::npos) << out.schedule.why_global;
}

TEST(WindowThreads, ThreadsSplitBetweenRealizationsAndWindows) {
  EXPECT_EQ(split_threads(2, 1).runs, 1u);
  EXPECT_EQ(split_threads(2, 1).per_run, 2u);  // one realization: both threads on its windows
  EXPECT_EQ(split_threads(2, 8).runs, 2u);
  EXPECT_EQ(split_threads(2, 8).per_run, 1u);
  EXPECT_EQ(split_threads(8, 3).runs, 3u);
  EXPECT_EQ(split_threads(8, 3).per_run, 2u);
  EXPECT_EQ(split_threads(1, 4).per_run, 1u);
}

TEST(WindowThreads, StreamedInitialConditionEqualsTheBodies) {
  // simulate(initial, k) reads the bodies in chunks; the run is that of the whole copy.
  InitialParams ip = gas(9000);
  ip.remove_mean = true;
  const ParticleParams p = params({Geometry::ring, 0.9, 1e-2, Subthreshold::elastic, 50.0}, 1);
  const RunResult streamed = simulate(ip, 3, p);
  const RunResult copied = simulate(make_initial_bodies(ip, 3), domain_length(ip), p);
  expect_identical(streamed, copied);
}

}  // namespace
}  // namespace shockgas::particles
