#pragma once
// Pearson's chi-square test of a sample against a continuous law, and the
// chi-square distribution's upper tail that turns the statistic into a p-value.
#include <cstddef>
#include <functional>
#include <span>
#include <vector>

namespace shockgas::compare {

// Q(a, x) = Gamma(a, x) / Gamma(a), the regularised upper incomplete gamma
// function: the series of P = 1 - Q for x < a + 1, else the continued fraction
// of Q (modified Lentz), each summed to rounding (Numerical Recipes, 6.2).
// Throws InputError unless a > 0 and x >= 0.
double regularized_gamma_q(double a, double x);

// P(X > x) for X chi-square with `dof` degrees of freedom: Q(dof / 2, x / 2).
double chi_square_survival(double x, std::size_t dof);

// The sample against a law with quantile function `quantile` on `bins`
// equiprobable bins (edges quantile(k / bins), k = 1..bins-1; the outer bins
// are open):
//     X^2 = sum_j (O_j - E)^2 / E,   E = n / bins,
// with dof = bins - 1 (no parameter fitted to the sample) and p = P(chi2_dof > X^2).
// For the chi-square approximation each bin should expect >~ 5 samples.
struct ChiSquareTest {
  double statistic = 0;               // X^2
  std::size_t dof = 0;                // bins - 1
  double p_value = 0;                 // P(chi2_dof > X^2)
  double expected = 0;                // E, samples expected per bin
  std::vector<double> edges;          // the bins - 1 inner edges, increasing
  std::vector<std::size_t> observed;  // O_j
};
// Throws InputError unless bins >= 2 and the sample holds >= 5 samples per bin.
ChiSquareTest chi_square_test(std::span<const double> sample, const std::function<double(double)>& quantile,
                              std::size_t bins);

}  // namespace shockgas::compare
