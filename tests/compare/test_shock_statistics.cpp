// The shock statistics over realizations (shock_statistics.hpp): their errors
// are the jackknife's, and the exact sticky gas from white noise passes the
// exact laws while a wrong law fails.
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

#include "shockgas/compare/shock_statistics.hpp"
#include "shockgas/core/error.hpp"
#include "shockgas/particles/simulate.hpp"

namespace shockgas::compare {
namespace {

constexpr std::size_t kN = 10000;
constexpr double kT = 1000;  // a = (4 t^2 / 3)^(1/3) = 110 particles: 1 << a << N

// The clusters of >= 2 particles of R realizations of the exact sticky gas
// (the hull) from uniform white noise at t = kT.
std::vector<Bodies> sticky_realizations(std::size_t R) {
  InitialParams ip;
  ip.N = kN;
  ip.seed = 7;
  particles::ParticleParams p;
  p.r = 0;
  p.solver = particles::ParticleSolver::hull;
  p.t_end = kT;
  p.samples = 1;
  const InitialCondition ic(ip);
  std::vector<Bodies> out;
  for (std::size_t k = 0; k < R; ++k)
    out.push_back(*particles::simulate(ic.realization(k), ic.length(), p).final_clusters);
  return out;
}

StatisticsShape white_noise_shape(double t = kT) {
  return {static_cast<double>(kN), static_cast<double>(kN), static_cast<double>(kN), t, true, 1.0 / 3.0};
}

TEST(ShockStatistics, TheExactStickyGasFollowsTheExactLaws) {
  const ShockStatistics s = shock_statistics(sticky_realizations(30), white_noise_shape());
  ASSERT_TRUE(s.mass.p_value && s.velocity.p_value);
  // The acceptance level: each law rejected only one time in a hundred when it holds.
  EXPECT_GT(*s.mass.p_value, 0.01) << *s.mass.chi2 << " on " << s.mass.dof;
  EXPECT_GT(*s.velocity.p_value, 0.01) << *s.velocity.chi2 << " on " << s.velocity.dof;
  EXPECT_GE(s.mass.bins_tested, 6u);
  EXPECT_GE(s.velocity.bins_tested, 10u);
  // The count above 1.5 particles within four of its standard errors of the exact expectation.
  ASSERT_TRUE(s.count_exact.has_value());
  EXPECT_LT(std::abs(s.count.value - *s.count_exact), 4 * s.count.error) << s.count.value;
}

TEST(ShockStatistics, AWrongLawIsRejected) {
  // The same clusters held against the laws of a gas twice as old (a 59 % larger
  // Lagrangian scale): the tests must see it, else they could not fail.
  const ShockStatistics s = shock_statistics(sticky_realizations(30), white_noise_shape(2 * kT));
  ASSERT_TRUE(s.mass.p_value && s.velocity.p_value);
  EXPECT_LT(*s.mass.p_value, 0.01);
  EXPECT_LT(*s.velocity.p_value, 0.01);
}

TEST(ShockStatistics, ErrorsAreTheJackknifeOverRealizations) {
  const std::vector<Bodies> runs = sticky_realizations(6);
  const ShockStatistics s = shock_statistics(runs, white_noise_shape());
  // For a mean the jackknife is s / sqrt(R) exactly (jackknife.hpp).
  std::vector<double> n;
  for (const Bodies& b : runs) n.push_back(static_cast<double>(b.size()));
  const double mean = std::accumulate(n.begin(), n.end(), 0.0) / 6;
  double ss = 0;
  for (double x : n) ss += (x - mean) * (x - mean);
  EXPECT_DOUBLE_EQ(s.count.value, mean);
  EXPECT_NEAR(s.count.error, std::sqrt(ss / 5 / 6), 1e-12 * mean);
  // The densities integrate to what they hold: every gap below 4 mean gaps, every
  // cluster's mass within |z| < 3 (a few in 10^4 beyond, none of a lone particle).
  double gaps = 0, mass = 0;
  for (std::size_t j = 0; j < s.spacing.value.size(); ++j)
    gaps += s.spacing.value[j] * (s.spacing.edges[j + 1] - s.spacing.edges[j]);
  for (std::size_t j = 0; j < s.velocity.value.size(); ++j)
    mass += s.velocity.value[j] * (s.velocity.edges[j + 1] - s.velocity.edges[j]);
  EXPECT_GT(gaps, 0.99);
  EXPECT_LE(gaps, 1 + 1e-12);
  EXPECT_GT(mass, 0.99);
  EXPECT_LE(mass, 1 + 1e-12);
}

// A bin no realization's cluster fell in is 0 with no error (the jackknife's 0
// would claim an exact 0); every other bin of a density keeps a finite one.
TEST(ShockStatistics, ABinEmptyInEveryRealizationHasNoError) {
  const ShockStatistics s = shock_statistics(sticky_realizations(6), white_noise_shape());
  std::size_t empty = 0;
  for (const BinnedStatistic* d : {&s.mass, &s.velocity, &s.spacing}) {
    ASSERT_EQ(d->value.size(), d->error.size());
    for (std::size_t j = 0; j < d->value.size(); ++j) {
      if (d->value[j] == 0) {
        ++empty;
        EXPECT_TRUE(std::isnan(d->error[j])) << "bin " << j << " of 0 with error " << d->error[j];
      } else {
        EXPECT_TRUE(std::isfinite(d->error[j])) << "bin " << j;
      }
    }
  }
  EXPECT_GT(empty, 0u);  // this seed leaves the velocity's outer bins empty: the case is met
}

TEST(ShockStatistics, OneRealizationGivesNoErrorAndNoMeanTest) {
  const ShockStatistics s = shock_statistics(sticky_realizations(1), white_noise_shape());
  EXPECT_TRUE(std::isnan(s.count.error));
  EXPECT_TRUE(std::isnan(s.mass_speed_correlation.error));
  EXPECT_FALSE(s.velocity.chi2.has_value());  // its errors come from realizations
  EXPECT_TRUE(s.mass.chi2.has_value());       // Poisson counts need none
}

TEST(ShockStatistics, WithoutWhiteNoiseNoLawIsApplied) {
  StatisticsShape shape = white_noise_shape();
  shape.white_noise_D.reset();
  const ShockStatistics s = shock_statistics(sticky_realizations(3), shape);
  EXPECT_TRUE(s.mass.exact.empty());
  EXPECT_FALSE(s.mass.chi2.has_value());
  EXPECT_FALSE(s.count_exact.has_value());
}

TEST(ShockStatistics, RefusesNoRealizations) {
  EXPECT_THROW(shock_statistics({}, white_noise_shape()), InputError);
}

}  // namespace
}  // namespace shockgas::compare
