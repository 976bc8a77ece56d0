#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "shockgas/compare/shock_detection.hpp"
#include "shockgas/core/error.hpp"
#include "synthetic_fields.hpp"

namespace shockgas::compare {
namespace {

// Positions and integrals of O(100) numbers over a few cells, divided by jumps of
// O(1): rounding ~ 1e-13; 1e-10 leaves room and would still catch an error of
// one part in 10^9 of a cell.
constexpr double kRound = 1e-10;

TEST(ShockDetection, RecoversExactSawtoothShocks) {
  const auto saw = testing::five_shock_sawtooth();
  for (std::size_t cells : {1000u, 1237u}) {
    const auto field = saw.cell_averages(cells);
    const auto shocks = detect_shocks(field.v, field.rho, field.length);
    ASSERT_EQ(shocks.size(), saw.X.size()) << cells << " cells";
    for (std::size_t k = 0; k < shocks.size(); ++k) {
      EXPECT_NEAR(shocks[k].x, saw.X[k], kRound) << "shock " << k;
      EXPECT_NEAR(shocks[k].jump, saw.jump(k), kRound) << "shock " << k;
      EXPECT_NEAR(shocks[k].mass, saw.mass(k), kRound) << "shock " << k;
      EXPECT_NEAR(shocks[k].v, saw.shock_speed(k), kRound) << "shock " << k;
    }
  }
}

TEST(ShockDetection, ShockOnACellFaceIsExact) {
  auto saw = testing::five_shock_sawtooth();
  saw.X[2] = 40.0;  // the face between cells 399 and 400 of 1000
  const auto field = saw.cell_averages(1000);
  const auto shocks = detect_shocks(field.v, field.rho, field.length);
  ASSERT_EQ(shocks.size(), 5u);
  EXPECT_NEAR(shocks[2].x, 40.0, kRound);
  EXPECT_NEAR(shocks[2].jump, saw.jump(2), kRound);
}

TEST(ShockDetection, SmearedShockCountsOnce) {
  // v = -tanh((x - 50) / dx) + 2 (x - 50) / L: a jump of -2 smeared over ~ 6 cells
  // on a ramp of slope 2 / L; periodic (v = 0 at x = 0 and x = L).
  const std::size_t n = 400;
  const double L = 100, dx = L / n;
  std::vector<double> v(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double x = (i + 0.5) * dx;
    v[i] = -std::tanh((x - 50) / dx) + 2 * (x - 50) / L;
  }
  const auto shocks = detect_shocks(v, {}, L);
  ASSERT_EQ(shocks.size(), 1u);
  // The profile is odd about x = 50: the position is exact to rounding.
  EXPECT_NEAR(shocks[0].x, 50.0, 1e-9);
  // The tanh tail outside the region (|x - 50| >= 4 cells, 1 - tanh 4 = 7e-4 and a
  // tail slope of 2.7e-3 per cell) biases the ramps extrapolated over ~ 9 cells:
  // a few 1e-3 at most (measured 2.4e-3).
  EXPECT_NEAR(shocks[0].jump, -2.0, 5e-3);
}

TEST(ShockDetection, SmoothCompressionIsNotAShock) {
  const std::size_t n = 1000;
  const double L = 100;
  std::vector<double> v(n);
  for (std::size_t i = 0; i < n; ++i) v[i] = std::sin(2 * std::numbers::pi * (i + 0.5) / n);
  // Steepest 8-cell drop: 8 * 2 pi / 1000 = 0.05 < 5% of the range 2 = 0.1.
  EXPECT_TRUE(detect_shocks(v, {}, L).empty());
}

// The Riemann problem v = 1 | 0 on the ring at t = 0.2, as the exact solver's
// cell averages give it: a fan rising at slope 1/t to 1, a plateau, the shock at
// 0.6. Where the fan meets the plateau the averages dropped by one rounding
// (2.2e-16); extrapolating the fan's slope made that a jump of -0.09, a second
// shock (found on hopf_lax's output).
TEST(ShockDetection, ARoundingDropAtTheEdgeOfAFanIsNoShock) {
  const std::size_t n = 64;
  const double dx = 1.0 / n, t = 0.2;
  // Cell averages of v(x) = x / t (x < t), 1 (t <= x < 0.6), 0 after: the
  // integral of v from 0 to x, differenced.
  auto integral = [t](double x) { return x < t ? x * x / (2 * t) : t / 2 + (std::min(x, 0.6) - t); };
  std::vector<double> v(n);
  for (std::size_t i = 0; i < n; ++i) v[i] = (integral((i + 1) * dx) - integral(i * dx)) / dx;
  v[14] = 1.0 - 2.2e-16;  // the plateau's second cell, one rounding below the first
  ASSERT_LT(v[14] - v[13], 0.0);
  const auto shocks = detect_shocks(v, {}, 1.0, {});
  ASSERT_EQ(shocks.size(), 1u);
  // A step between flat states inside a cell: the conserving position is exact.
  EXPECT_NEAR(shocks[0].x, 0.6, 1e-12);
  EXPECT_NEAR(shocks[0].jump, -1.0, 1e-12);
}

TEST(ShockDetection, UsesTheSolversOwnListWhenItHasOne) {
  continuum::ContinuumResult r;
  r.length = 10;
  r.v.assign(10, 0.0);
  r.has_shocks = true;
  r.shocks = {continuum::Shock{1.5, 2.0, -0.3, 0.1}};
  const auto shocks = find_shocks(r);
  ASSERT_EQ(shocks.size(), 1u);
  EXPECT_EQ(shocks[0].x, 1.5);
  EXPECT_EQ(shocks[0].mass, 2.0);
}

TEST(ShockDetection, RejectsBadInput) {
  EXPECT_THROW(detect_shocks(std::vector<double>(3, 0.0), {}, 1.0), InputError);
  EXPECT_THROW(detect_shocks(std::vector<double>(10, 0.0), {}, 0.0), InputError);
  EXPECT_THROW(detect_shocks(std::vector<double>(10, 0.0), std::vector<double>(9, 0.0), 1.0), InputError);
}

}  // namespace
}  // namespace shockgas::compare
