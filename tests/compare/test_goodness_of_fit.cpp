#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "shockgas/compare/goodness_of_fit.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::compare {
namespace {

TEST(GoodnessOfFit, IncompleteGammaAgainstClosedFormsAndScipy) {
  // Closed forms: Q(1, x) = e^-x, Q(1/2, x) = erfc(sqrt x); both branches (x < a+1, x >= a+1).
  for (double x : {0.1, 1.0, 1.9, 2.5, 10.0, 40.0}) {
    EXPECT_NEAR(regularized_gamma_q(1.0, x) / std::exp(-x), 1.0, 1e-14) << x;
    EXPECT_NEAR(regularized_gamma_q(0.5, x) / std::erfc(std::sqrt(x)), 1.0, 1e-13) << x;
  }
  EXPECT_EQ(regularized_gamma_q(3.0, 0.0), 1.0);
  // scipy.special.gammaincc (SciPy 1.10), to 1e-13 relative.
  EXPECT_NEAR(regularized_gamma_q(7.5, 3.0), 0.9797477467178134, 1e-13);
  EXPECT_NEAR(regularized_gamma_q(7.5, 12.0), 0.06509348639883054, 1e-14);
  EXPECT_NEAR(regularized_gamma_q(200.0, 180.0), 0.9251419650158405, 1e-13);
  EXPECT_THROW(regularized_gamma_q(0.0, 1.0), InputError);
  EXPECT_THROW(regularized_gamma_q(1.0, -1.0), InputError);
}

TEST(GoodnessOfFit, ChiSquareSurvivalAgainstScipy) {
  // scipy.stats.chi2.sf: the 5% point of 19 dof, and a far tail.
  EXPECT_NEAR(chi_square_survival(30.143527205646155, 19), 0.05, 1e-14);
  EXPECT_NEAR(chi_square_survival(19.6, 19), 0.41899856526862594, 1e-14);
  EXPECT_NEAR(chi_square_survival(80.0, 19) / 1.8596255029858537e-09, 1.0, 1e-12);
  EXPECT_NEAR(chi_square_survival(3.0, 2), std::exp(-1.5), 1e-15);  // 2 dof: e^(-x/2)
}

TEST(GoodnessOfFit, PearsonStatisticByHand) {
  // Uniform law on [0, 1] (quantile = identity), 4 bins, 20 samples: counts 8, 4, 4, 4,
  // E = 5, X^2 = (9 + 1 + 1 + 1) / 5 = 2.4 with 3 dof.
  std::vector<double> sample;
  for (int k = 0; k < 8; ++k) sample.push_back(0.01 + 0.02 * k);
  for (double start : {0.3, 0.6, 0.8})
    for (int k = 0; k < 4; ++k) sample.push_back(start + 0.01 * k);
  const ChiSquareTest t = chi_square_test(
      sample, [](double p) { return p; }, 4);
  EXPECT_EQ(t.observed, (std::vector<std::size_t>{8, 4, 4, 4}));
  EXPECT_DOUBLE_EQ(t.expected, 5.0);
  EXPECT_NEAR(t.statistic, 2.4, 1e-14);
  EXPECT_EQ(t.dof, 3u);
  EXPECT_NEAR(t.p_value, chi_square_survival(2.4, 3), 1e-15);
  EXPECT_THROW(chi_square_test(
                   sample, [](double p) { return p; }, 5),
               InputError);  // < 5 per bin
}

}  // namespace
}  // namespace shockgas::compare
