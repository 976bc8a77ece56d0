#include <gtest/gtest.h>

#include <cmath>

#include "shockgas/compare/statistics.hpp"
#include "shockgas/core/error.hpp"
#include "shockgas/core/random.hpp"

namespace shockgas::compare {
namespace {

TEST(Statistics, QuantilesInterpolateOrderStatistics) {
  // Type 7 on 1..5: h = p (n - 1); the values are exact in binary.
  const std::vector<double> v{5, 1, 4, 2, 3};
  EXPECT_EQ(quantile(v, 0.0), 1.0);
  EXPECT_EQ(quantile(v, 1.0), 5.0);
  EXPECT_EQ(quantile(v, 0.5), 3.0);
  EXPECT_EQ(quantile(v, 0.125), 1.5);
  const Quartiles q = quartiles(v);
  EXPECT_EQ(q.q25, 2.0);
  EXPECT_EQ(q.q75, 4.0);
  EXPECT_THROW(quantile({}, 0.5), InputError);
  EXPECT_THROW(quantile(v, 1.5), InputError);
}

TEST(Statistics, LineFitIsExactOnALine) {
  std::vector<double> x, y;
  for (int i = 0; i < 20; ++i) {
    x.push_back(0.1 * i);
    y.push_back(-3.0 + 2.5 * x.back());
  }
  const LineFit f = fit_line(x, y);
  // QR on 20 O(1) rows: a few ulps of the O(1) coefficients.
  EXPECT_NEAR(f.slope, 2.5, 1e-12);
  EXPECT_NEAR(f.intercept, -3.0, 1e-12);
  EXPECT_NEAR(f.slope_error, 0.0, 1e-12);
  EXPECT_EQ(f.points, 20u);
}

TEST(Statistics, LineFitStandardErrorMatchesScatter) {
  // y = 1 + 2 x + noise of sd 0.1 at 2000 points x in [0, 1): the textbook
  // standard error of the slope is sd / sqrt(sum (x - mean)^2) = 0.1 / sqrt(2000 / 12).
  Rng rng(3);
  std::vector<double> x, y;
  for (int i = 0; i < 2000; ++i) {
    x.push_back(i / 2000.0);
    y.push_back(1 + 2 * x.back() + 0.1 * rng.normal());
  }
  const LineFit f = fit_line(x, y);
  const double expected_se = 0.1 / std::sqrt(2000.0 / 12.0);
  // The estimated sd has relative scatter 1/sqrt(2 n) ~ 1.6%: 10% is > 6 sigma.
  EXPECT_NEAR(f.slope_error, expected_se, 0.1 * expected_se);
  // The slope is within 5 standard errors of the truth.
  EXPECT_NEAR(f.slope, 2.0, 5 * expected_se);
}

TEST(Statistics, ZeroWeightsDropPoints) {
  const std::vector<double> x{0, 1, 2, 3}, y{0, 1, 100, 3}, w{1, 1, 0, 1};
  const LineFit f = fit_line(x, y, w);
  EXPECT_NEAR(f.slope, 1.0, 1e-12);  // rounding of an exact fit on O(1) data
  EXPECT_EQ(f.points, 3u);
  EXPECT_THROW(fit_line(std::vector<double>{1, 1}, std::vector<double>{0, 1}), InputError);
}

}  // namespace
}  // namespace shockgas::compare
