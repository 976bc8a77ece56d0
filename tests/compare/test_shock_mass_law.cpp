#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "shockgas/compare/cluster_velocity_law.hpp"
#include "shockgas/compare/shock_mass_law.hpp"
#include "shockgas/compare/white_noise_references.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::compare {
namespace {

// int N = n_s: the shock density of the velocity law, integrated there over
// the velocity u last and here over u first (inside N(mu)): two quadratures of
// one double integral, measured to agree to 3e-15.
TEST(ShockMassLaw, CountsTheShockDensity) {
  EXPECT_NEAR(shock_mass_integral(0, 12), cluster_velocity_law().shock_density(), 1e-12);
  EXPECT_NEAR(shock_mass_integral(0, 12), 2.1085, 5e-5);  // as quoted in cluster_velocity_law.hpp, 4 digits
}

// int mu N(mu) dmu = 1: every particle sits in a shock. This checks the factor 2
// and K's normalisation of the intensity, which n_s alone would not (both
// integrals are of the same intensity). 3-point Gauss-Legendre in sqrt(mu):
// measured 1 + 4e-15.
TEST(ShockMassLaw, HoldsAllTheMass) {
  double mass = 0;
  for (int p = 0; p < 480; ++p) {  // mu in [0, 12] through v = sqrt(mu) in [0, 3.46], 480 panels
    const double v0 = std::sqrt(12.0) * p / 480, v1 = std::sqrt(12.0) * (p + 1) / 480;
    // 3-point Gauss-Legendre on [v0, v1] of 2 v mu N(mu) dv
    const double c = 0.5 * (v0 + v1), h = 0.5 * (v1 - v0), q = std::sqrt(0.6);
    for (const auto& [x, w] : {std::pair{-q, 5.0 / 9}, {0.0, 8.0 / 9}, {q, 5.0 / 9}}) {
      const double v = c + h * x;
      mass += h * w * 2 * v * v * v * shock_mass_density(v * v);
    }
  }
  EXPECT_NEAR(mass, 1.0, 1e-12);
}

// N(mu) -> (2 / pi)^(1/2) mu^(-1/2): the excursion limit of K times (g * g)(0) = 2.
// The next terms are O(mu^(1/2)) relative (K's -1/4 against mu^(-3/2)).
TEST(ShockMassLaw, SmallShocksFollowTheExcursionLimit) {
  for (double mu : {1e-6, 1e-4}) {
    const double limit = std::sqrt(2 / std::numbers::pi / mu);
    EXPECT_NEAR(shock_mass_density(mu) / limit, 1.0, 3 * std::sqrt(mu)) << mu;
  }
  EXPECT_THROW(shock_mass_density(0), InputError);
}

// In the gas's units: a ring of N = L unit masses from uniform velocities on
// [-1, 1] (D = 1/3) holds 1.916 N t^(-2/3) shocks in all, the figure of
// docs/paper.md; the bins add up to the integral over their union.
TEST(ShockMassLaw, BinsInTheGasUnitsAddUpToTheShockCount) {
  const double D = 1.0 / 3, L = 1e6, t = 1000;
  const std::vector<double> all{0.0, 1e6};
  const double n = expected_shocks_in_mass_bins(all, D, L, 1.0, t).front();
  EXPECT_NEAR(n / (L * std::pow(t, -2.0 / 3)), 1.9157, 5e-5);  // 4 digits, as quoted
  const std::vector<double> edges{0.0, 1.5, 2.5, 4.5, 8.5, 1e6};
  double sum = 0;
  for (double c : expected_shocks_in_mass_bins(edges, D, L, 1.0, t)) sum += c;
  EXPECT_NEAR(sum / n, 1.0, 1e-10);
  EXPECT_THROW(expected_shocks_in_mass_bins(std::vector<double>{2, 1}, D, L, 1.0, t), InputError);
}

// The shocks above a mass: all of them from 0 (1.916 N t^(-2/3), as above), the
// heavy bins' sum above an edge (the same integrand on other panels: the
// quadrature's own error, measured below 1e-13 relative), none beyond the law's
// cut-off mu = 12 (e^-288 of its scale).
TEST(ShockMassLaw, ShocksAboveAMassAreTheBinsAboveIt) {
  const double D = 1.0 / 3, L = 1e6, t = 1000, a = std::cbrt(4 * D * t * t);
  EXPECT_NEAR(expected_shocks_above(0, D, L, 1.0, t) / (L * std::pow(t, -2.0 / 3)), 1.9157, 5e-5);
  const std::vector<double> edges{1.5, 2.5, 4.5, 8.5, 13 * a};
  double heavy = 0;
  for (double c : expected_shocks_in_mass_bins(edges, D, L, 1.0, t)) heavy += c;
  EXPECT_NEAR(expected_shocks_above(1.5, D, L, 1.0, t) / heavy, 1.0, 1e-12);
  EXPECT_EQ(expected_shocks_above(13 * a, D, L, 1.0, t), 0.0);
  EXPECT_THROW(expected_shocks_above(-1, D, L, 1.0, t), InputError);
}

// At many times in one sweep (pieces of the quadrature added from the cut-off
// down) as at each alone: the same integrand on other panels, so the same to the
// quadrature's error (measured below 1e-13 relative); in the order of the times given.
TEST(ShockMassLaw, ShocksAboveAMassInTimeAreThoseAtEachTime) {
  const double D = 1.0 / 3, L = 1e4;
  const std::vector<double> times{1000, 1, 10, 1e5, 100, 3};
  const std::vector<double> swept = expected_shocks_above(1.5, D, L, 1.0, times);
  ASSERT_EQ(swept.size(), times.size());
  for (std::size_t k = 0; k < times.size(); ++k)
    EXPECT_NEAR(swept[k] / expected_shocks_above(1.5, D, L, 1.0, times[k]), 1.0, 1e-12) << times[k];
  EXPECT_GT(swept[0], swept[3]);  // fewer shocks at later times
}

// The references of a white-noise start: T t^(2/3) -> 0.2129 and 1.916 N t^(-2/3)
// shocks for the gas's uniform velocities (docs/paper.md); nothing for other starts.
TEST(WhiteNoiseReferences, TheGasStartHasTheQuotedLaws) {
  InitialParams p;
  p.N = 5000;
  const auto r = white_noise_references(p);
  ASSERT_TRUE(r);
  EXPECT_NEAR(cluster_law_second_moment(), 0.1757064, 1e-7);  // 7 digits, as in test_cluster_velocity_law.cpp
  EXPECT_NEAR(r->temperature_amplitude, 0.2129, 5e-5);        // 4 digits, as quoted
  EXPECT_NEAR(r->shock_count_coefficient / 5000, 1.9157, 5e-5);
  p.positions = Positions::random;
  EXPECT_FALSE(white_noise_references(p));
}

}  // namespace
}  // namespace shockgas::compare
