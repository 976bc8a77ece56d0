#include <gtest/gtest.h>

#include <cmath>

#include "shockgas/compare/theory.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::compare {
namespace {

TEST(Theory, CrossoverTimesAndShockCount) {
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

TEST(Theory, CoolingLawsMeetAtTheStickingTime) {
  // BCDR eq. 3: eps^-2 t^-2 = t^(-2/3) at t_stick = eps^(-3/2), where T ~ eps.
  for (double r : {0.9, 0.99}) {
    const double eps = inelasticity(r), t = sticking_time(r);
    EXPECT_NEAR(sticky_gas_temperature(t), eps, 1e-12 * eps);
    // (1 + eps t)^-2 -> eps^-2 t^-2 for eps t >> 1: within 2 / (eps t) relative.
    const double asymptote = 1.0 / (eps * eps * t * t);
    EXPECT_NEAR(homogeneous_cooling_temperature(r, t) / asymptote, 1.0, 2.0 / (eps * t));
  }
}

TEST(Theory, AutomaticClusterThreshold) {
  // A tenth of the typical cluster mass t^(2/3), at least 2 particles.
  EXPECT_EQ(automatic_min_cluster_particles(1.0), 2.0);
  EXPECT_NEAR(automatic_min_cluster_particles(1e6), 1e3, 1e-9);  // 0.1 (1e6)^(2/3) = 1000
  EXPECT_NEAR(validity_time(1e-2), 1e6, 1e-6);
}

}  // namespace
}  // namespace shockgas::compare
