#include "shockgas/compare/scaling_laws.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "shockgas/core/error.hpp"

namespace shockgas::compare {
namespace {

TEST(ScalingLaws, CrossoverTimesAndShockCount) {
  // Exact in binary up to a rounding of pow: 1e-12 relative.
  EXPECT_NEAR(dissipation_time(0.9), 20.0, 1e-12);
  EXPECT_NEAR(sticking_time(0.9), std::pow(0.05, -1.5), 1e-12);
  EXPECT_NEAR(dissipation_time(0.0), 2.0, 1e-15);
  EXPECT_TRUE(std::isinf(sticking_time(1.0)));
  // The paper's Fig. 5: N = 2e4, t = 1e5 -> about 9 shocks.
  EXPECT_NEAR(expected_shock_count(2e4, 1e5), 2e4 * std::pow(1e5, -2.0 / 3.0), 1e-9);
  EXPECT_NEAR(expected_shock_count(2e4, 1e5), 9.28, 0.01);
  EXPECT_NEAR(shock_count_ratio(9, 2e4, 1e5), 9 / 9.2832, 1e-3);
  EXPECT_NEAR(scaled_velocity(0.5, 8.0), 1.0, 1e-15);
  EXPECT_THROW(inelasticity(1.5), InputError);
  EXPECT_THROW(expected_shock_count(0, 1), InputError);
}

}  // namespace
}  // namespace shockgas::compare
