// Ensembles: deterministic whatever the number of threads, and the statistics
// they report.
#include <gtest/gtest.h>

#include <cmath>

#include "shockgas/particles/simulate.hpp"

namespace shockgas::particles {
namespace {

InitialParams small_gas() {
  InitialParams ip;
  ip.N = 1000;
  ip.seed = 42;
  return ip;
}

ParticleParams four_realizations(std::size_t threads) {
  ParticleParams p;
  p.r = 0.5;
  p.t_end = 200.0;
  p.samples = 12;
  p.realizations = 4;
  p.threads = threads;
  p.histogram_bins = 16;
  return p;
}

TEST(Ensemble, BitIdenticalWithOneAndTwoThreads) {
  const EnsembleResult one = run_ensemble(small_gas(), four_realizations(1));
  const EnsembleResult two = run_ensemble(small_gas(), four_realizations(2));
  ASSERT_EQ(one.t.size(), 12u);
  EXPECT_EQ(one.t, two.t);
  EXPECT_EQ(one.T.mean, two.T.mean);  // exact equality: the same sums in the same order
  EXPECT_EQ(one.T.stderr_, two.T.stderr_);
  EXPECT_EQ(one.collisions.mean, two.collisions.mean);
  EXPECT_EQ(one.n_clusters.mean, two.n_clusters.mean);
  EXPECT_EQ(one.histogram, two.histogram);
  EXPECT_EQ(one.collisions_per_realization, two.collisions_per_realization);
  EXPECT_EQ(one.first.final_state.v, two.first.final_state.v);
}

TEST(Ensemble, MeanAndStandardErrorOverRealizations) {
  ParticleParams p = four_realizations(2);
  const EnsembleResult e = run_ensemble(small_gas(), p);
  // The realizations differ (distinct seeds), so the standard error is > 0 ...
  EXPECT_GT(e.T.stderr_.back(), 0.0);
  // ... and the first realization alone is one of the averaged ones.
  p.realizations = 1;
  const EnsembleResult single = run_ensemble(small_gas(), p);
  EXPECT_EQ(single.first.series.T, e.first.series.T);
  EXPECT_EQ(single.T.stderr_.back(), 0.0);
  for (double c : e.count) EXPECT_EQ(c, 4.0);
  // The temperature has dropped well below its initial 1/3 by t = 200 (r = 0.5).
  EXPECT_LT(e.T.mean.back(), 0.05);
}

TEST(Ensemble, KeepsEachRealizationsSeriesForTheJackknife) {
  const EnsembleResult e = run_ensemble(small_gas(), four_realizations(2));
  ASSERT_EQ(e.T_by_realization.size(), 4u);
  ASSERT_EQ(e.histogram_by_realization.size(), 4u);
  EXPECT_EQ(e.T_by_realization.front(), e.first.series.T);
  EXPECT_EQ(e.histogram_by_realization.front(), e.first.histogram.density);
  // Their means are the ensemble's (the same sums, to rounding).
  for (std::size_t k = 0; k < e.t.size(); ++k) {
    double sum = 0;
    for (const auto& row : e.T_by_realization) sum += row[k];
    EXPECT_NEAR(sum / 4, e.T.mean[k], 1e-15 * e.T.mean[k]);
  }
}

TEST(Ensemble, ProgressIsReportedAndEnds) {
  double last = -1;
  ParticleParams p = four_realizations(2);
  run_ensemble(small_gas(), p, [&](double fraction, double, std::uint64_t) { last = fraction; });
  EXPECT_DOUBLE_EQ(last, 1.0);  // every realization reports completion
}

}  // namespace
}  // namespace shockgas::particles
