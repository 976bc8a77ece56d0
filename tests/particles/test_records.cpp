// The optional records of a run: snapshots, the scaled-velocity histogram, the
// space-time record, and the sample schedule.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

#include "shockgas/core/error.hpp"
#include "shockgas/core/initial_condition.hpp"
#include "shockgas/particles/simulate.hpp"

namespace shockgas::particles {
namespace {

Bodies gas(std::size_t n) {
  InitialParams ip;
  ip.N = n;
  ip.seed = 9;
  return make_initial_bodies(ip);
}

TEST(Records, SamplesAreLogSpacedFromOneToTheEnd) {
  ParticleParams p;
  p.t_end = 1000.0;
  p.samples = 4;
  const RunResult out = simulate(gas(500), 500.0, p);
  ASSERT_EQ(out.series.size(), 4u);
  const double rel = 1e-14;  // pow() rounding
  EXPECT_EQ(out.series.t[0], 1.0);
  EXPECT_NEAR(out.series.t[1], 10.0, 10.0 * rel);
  EXPECT_NEAR(out.series.t[2], 100.0, 100.0 * rel);
  EXPECT_EQ(out.series.t[3], 1000.0);
  for (std::size_t k = 1; k < 4; ++k) EXPECT_GE(out.series.collisions[k], out.series.collisions[k - 1]);
  EXPECT_EQ(out.series.n_clusters.size(), 4u);
}

TEST(Records, SnapshotsAtTheRequestedTimes) {
  ParticleParams p;
  p.t_end = 50.0;
  p.snapshots = {20.0, 5.0};
  const RunResult out = simulate(gas(500), 500.0, p);
  ASSERT_EQ(out.snapshots.size(), 2u);
  EXPECT_EQ(out.snapshots[0].t, 5.0);
  EXPECT_EQ(out.snapshots[1].t, 20.0);
  EXPECT_EQ(out.snapshots[1].bodies.size(), 500u);
}

TEST(Records, HistogramIsADensityOfMass) {
  ParticleParams p;
  p.t_end = 100.0;
  p.samples = 3;
  p.histogram_bins = 40;
  p.histogram_zmax = 10.0;  // wide enough to hold all the mass: |v| <= 1, t^(1/3) <= 4.7
  const RunResult out = simulate(gas(1000), 1000.0, p);
  ASSERT_EQ(out.histogram.t.size(), 3u);
  ASSERT_EQ(out.histogram.density.size(), 3u * 40u);
  const double dz = 2 * 10.0 / 40;
  for (std::size_t k = 0; k < 3; ++k) {
    double mass = 0;
    for (std::size_t b = 0; b < 40; ++b) mass += out.histogram.density[k * 40 + b] * dz;
    EXPECT_NEAR(mass, 1.0, 1e-12);  // sum of 1000 fractions: rounding only
  }
}

TEST(Records, SpaceTimeFollowsEveryParticle) {
  ParticleParams p;
  p.r = 0.0;  // merges: merged particles share their cluster's position
  p.delta = 0.0;
  p.t_end = 100.0;
  p.spacetime = true;
  p.spacetime_frames = 11;
  const Bodies b = gas(200);
  const RunResult out = simulate(b, 200.0, p);
  ASSERT_EQ(out.spacetime.t.size(), 11u);
  ASSERT_EQ(out.spacetime.x.size(), 11u * 200u);
  EXPECT_EQ(out.spacetime.t[10], 100.0);
  for (std::size_t i = 0; i < 200; ++i) EXPECT_EQ(out.spacetime.x[i], b.x[i]);  // frame 0 is t = 0
  // The last frame holds as many distinct positions as there are bodies.
  std::vector<double> last(out.spacetime.x.end() - 200, out.spacetime.x.end());
  std::sort(last.begin(), last.end());
  EXPECT_EQ(static_cast<std::size_t>(std::unique(last.begin(), last.end()) - last.begin()),
            out.final_state.size());
}

// The labels kept: K = min(n, most), increasing, the first and the last always,
// gaps that differ by at most one (floor(k (n - 1) / (K - 1))).
TEST(Records, SpaceTimeLabelsAreEvenlySpaced) {
  EXPECT_EQ(spacetime_labels(5, 2000), (std::vector<std::size_t>{0, 1, 2, 3, 4}));
  EXPECT_EQ(spacetime_labels(10, 4), (std::vector<std::size_t>{0, 3, 6, 9}));
  EXPECT_EQ(spacetime_labels(1, 2), (std::vector<std::size_t>{0}));
  for (std::size_t n : {2u, 3u, 1999u, 2000u, 2001u, 20000u, 100000u}) {
    const auto labels = spacetime_labels(n, 2000);
    ASSERT_EQ(labels.size(), std::min<std::size_t>(n, 2000)) << n;
    EXPECT_EQ(labels.front(), 0u) << n;
    EXPECT_EQ(labels.back(), n - 1) << n;
    std::vector<std::size_t> gaps(labels.size());
    std::adjacent_difference(labels.begin(), labels.end(), gaps.begin());
    const auto [least, most] = std::minmax_element(gaps.begin() + 1, gaps.end());
    EXPECT_GE(*least, 1u) << n;
    EXPECT_LE(*most - *least, 1u) << n;
  }
}

// A record of fewer world lines holds the whole record's columns at its labels, bit for bit.
TEST(Records, SpaceTimeOfFewerParticlesIsTheWholeRecordAtTheirLabels) {
  ParticleParams p;
  p.r = 0.5;
  p.delta = 1e-2;
  p.t_end = 100.0;
  p.spacetime = true;
  p.spacetime_frames = 11;
  const Bodies b = gas(200);
  const RunResult whole = simulate(b, 200.0, p);
  p.spacetime_particles = 9;
  const RunResult some = simulate(b, 200.0, p);
  ASSERT_EQ(whole.spacetime.labels.size(), 200u);
  ASSERT_EQ(some.spacetime.labels, spacetime_labels(200, 9));
  ASSERT_EQ(some.spacetime.x.size(), 11u * 9u);
  EXPECT_EQ(some.spacetime.t, whole.spacetime.t);
  for (std::size_t f = 0; f < 11; ++f)
    for (std::size_t j = 0; j < 9; ++j)
      EXPECT_EQ(some.spacetime.x[f * 9 + j], whole.spacetime.x[f * 200 + some.spacetime.labels[j]])
          << f << " " << j;
  EXPECT_EQ(some.final_state.x, whole.final_state.x);  // the record does not touch the run
}

TEST(Records, BadInputNamesTheKey) {
  ParticleParams p;
  Bodies unsorted = gas(10);
  std::swap(unsorted.x[2], unsorted.x[5]);
  EXPECT_THROW(simulate(unsorted, 10.0, p), InputError);
  p.r = 1.5;
  try {
    simulate(gas(10), 10.0, p);
    FAIL() << "r = 1.5 accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "particles.r");
  }
}

}  // namespace
}  // namespace shockgas::particles
