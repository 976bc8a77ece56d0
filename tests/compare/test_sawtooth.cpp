#include <gtest/gtest.h>

#include <cmath>

#include "shockgas/compare/sawtooth.hpp"
#include "shockgas/compare/shock_detection.hpp"
#include "shockgas/core/error.hpp"
#include "shockgas/core/random.hpp"
#include "synthetic_fields.hpp"

namespace shockgas::compare {
namespace {

TEST(Sawtooth, ExactRampsGiveSlopeTimesTOne) {
  const auto saw = testing::five_shock_sawtooth();
  const auto field = saw.cell_averages(1000);
  const SawtoothFit fit = fit_sawtooth_slopes(field.v, field.length, field.t, saw.X);
  ASSERT_EQ(fit.ramps.size(), 5u);
  for (const RampFit& r : fit.ramps) {
    // Cell averages of a linear ramp are exact; QR on <= 600 O(100) rows: ~1e-13.
    EXPECT_NEAR(r.slope_times_t, 1.0, 1e-10) << "ramp " << r.left_shock;
  }
  // The last ramp wraps across x = L: from 99.96 to 102.03; centres in [100.21, 101.78]: 16 cells.
  EXPECT_NEAR(fit.ramps.back().x_end, 102.03, 1e-12);
  EXPECT_EQ(fit.ramps.back().cells, 16u);
  EXPECT_NEAR(fit.slope_times_t.median, 1.0, 1e-10);
  EXPECT_NEAR(fit.slope_times_t.q25, 1.0, 1e-10);
  EXPECT_NEAR(fit.slope_times_t.q75, 1.0, 1e-10);
}

TEST(Sawtooth, DetectedShocksFeedTheFit) {
  const auto saw = testing::five_shock_sawtooth();
  const auto field = saw.cell_averages(800);
  std::vector<double> xs;
  for (const auto& s : detect_shocks(field.v, field.rho, field.length)) xs.push_back(s.x);
  const SawtoothFit fit = fit_sawtooth_slopes(field.v, field.length, field.t, xs);
  ASSERT_EQ(fit.ramps.size(), 5u);
  EXPECT_NEAR(fit.slope_times_t.median, 1.0, 1e-10);  // as above
}

TEST(Sawtooth, NoisyRampsScatterAroundOne) {
  // Slope 1/t plus noise of sd 1e-3 on cells of 0.1: each ramp's slope * t has a
  // standard error t * 1e-3 / sqrt(sum (x - mean)^2); the fit reports it.
  auto saw = testing::five_shock_sawtooth();
  auto field = saw.cell_averages(1000);
  Rng rng(23);
  for (double& v : field.v) v += 1e-3 * rng.normal();
  const SawtoothFit fit = fit_sawtooth_slopes(field.v, field.length, field.t, saw.X);
  ASSERT_EQ(fit.ramps.size(), 5u);
  for (const RampFit& r : fit.ramps) {
    // Within 5 reported standard errors of the truth.
    EXPECT_NEAR(r.slope_times_t, 1.0, 5 * r.slope_error * saw.t) << "ramp " << r.left_shock;
    EXPECT_GT(r.slope_error, 0.0);
  }
}

TEST(Sawtooth, ZeroWeightCellsAreSkippedAndShortRampsDropped) {
  const auto saw = testing::five_shock_sawtooth();
  auto field = saw.cell_averages(1000);
  std::vector<double> weights(field.v.size(), 1.0);
  for (std::size_t i = 0; i < weights.size(); i += 2) {
    weights[i] = 0.0;
    field.v[i] = 1e6;  // garbage the fit must not see
  }
  SawtoothParams p;
  p.min_cells = 10;  // the wrapping ramp keeps 8 of its 16 cells: dropped
  const SawtoothFit fit = fit_sawtooth_slopes(field.v, field.length, field.t, saw.X, p, weights);
  ASSERT_EQ(fit.ramps.size(), 4u);
  for (const RampFit& r : fit.ramps) EXPECT_NEAR(r.slope_times_t, 1.0, 1e-10);
}

TEST(Sawtooth, RampsBetweenExtendedObjects) {
  // The sawtooth with flat "clusters" of width 1 centred on each shock: ramps
  // from one cluster's right end to the next one's left end are still exact.
  const auto saw = testing::five_shock_sawtooth();
  auto field = saw.cell_averages(1000);
  std::vector<Extent> extents;
  for (double x : saw.X) {
    const double left = x - 0.5 < 0 ? x - 0.5 + saw.L : x - 0.5;
    extents.push_back(Extent{left, left + 1.0});
  }
  // Keep them sorted by left end (99.46 stays last; none wraps below 0 here).
  const double dx = saw.L / 1000;
  for (const auto& e : extents)
    for (std::size_t i = 0; i < field.v.size(); ++i) {
      const double x = (i + 0.5) * dx;
      if (x >= e.left && x <= e.right) field.v[i] = 123.0;  // flat cluster interiors
    }
  const SawtoothFit fit = fit_sawtooth_between(field.v, field.length, field.t, extents);
  ASSERT_EQ(fit.ramps.size(), 5u);
  for (const RampFit& r : fit.ramps) EXPECT_NEAR(r.slope_times_t, 1.0, 1e-10);  // as above
  EXPECT_NEAR(fit.ramps[4].x_begin, 100.46, 1e-12);  // the last cluster ends past L
}

TEST(Sawtooth, NoShocksNoRamps) {
  const SawtoothFit fit = fit_sawtooth_slopes(std::vector<double>(10, 0.0), 1.0, 1.0, {});
  EXPECT_TRUE(fit.ramps.empty());
  EXPECT_TRUE(std::isnan(fit.slope_times_t.median));
  EXPECT_THROW(fit_sawtooth_slopes(std::vector<double>(10, 0.0), 1.0, 0.0, {}), InputError);
  EXPECT_THROW(fit_sawtooth_slopes(std::vector<double>(10, 0.0), 1.0, 1.0, {1.5}), InputError);
}

}  // namespace
}  // namespace shockgas::compare
