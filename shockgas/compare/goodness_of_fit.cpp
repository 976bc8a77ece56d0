#include "shockgas/compare/goodness_of_fit.hpp"

#include <algorithm>
#include <cmath>

#include "shockgas/core/error.hpp"

namespace shockgas::compare {

namespace {

constexpr double kTiny = 1e-300;
constexpr int kMaxTerms = 10000;

// e^-x x^a / Gamma(a), the common factor of the series and the fraction.
double gamma_prefactor(double a, double x) { return std::exp(-x + a * std::log(x) - std::lgamma(a)); }

// P(a, x) = e^-x x^a / Gamma(a + 1) sum_n x^n / ((a+1)...(a+n)), for x < a + 1.
double lower_series(double a, double x) {
  double term = 1.0 / a, sum = term;
  for (int n = 1; n < kMaxTerms && term > sum * 1e-17; ++n) {
    term *= x / (a + n);
    sum += term;
  }
  return sum * gamma_prefactor(a, x);
}

// Q(a, x) = e^-x x^a / Gamma(a) * 1/(x+1-a- 1(1-a)/(x+3-a- 2(2-a)/(x+5-a- ...))), x >= a + 1.
double upper_fraction(double a, double x) {
  double b = x + 1 - a, c = 1 / kTiny, d = 1 / b, h = d;
  for (int n = 1; n < kMaxTerms; ++n) {
    const double an = -n * (n - a);
    b += 2;
    d = an * d + b;
    if (std::abs(d) < kTiny) d = kTiny;
    c = b + an / c;
    if (std::abs(c) < kTiny) c = kTiny;
    d = 1 / d;
    const double delta = d * c;
    h *= delta;
    if (std::abs(delta - 1) < 1e-16) break;
  }
  return gamma_prefactor(a, x) * h;
}

}  // namespace

double regularized_gamma_q(double a, double x) {
  require_above("gamma.a", a, 0.0);
  require(x >= 0 && std::isfinite(x), "gamma.x", x, "finite and >= 0");
  if (x == 0) return 1.0;
  return x < a + 1 ? 1.0 - lower_series(a, x) : upper_fraction(a, x);
}

double chi_square_survival(double x, std::size_t dof) {
  require(dof >= 1, "chi_square.dof", dof, ">= 1");
  return regularized_gamma_q(0.5 * static_cast<double>(dof), 0.5 * x);
}

ChiSquareTest chi_square_test(std::span<const double> sample, const std::function<double(double)>& quantile,
                              std::size_t bins) {
  require(bins >= 2, "chi_square.bins", bins, ">= 2");
  require(sample.size() >= 5 * bins, "chi_square.samples", sample.size(),
          ">= 5 per bin (" + std::to_string(5 * bins) + ")");
  ChiSquareTest test;
  for (std::size_t k = 1; k < bins; ++k)
    test.edges.push_back(quantile(static_cast<double>(k) / static_cast<double>(bins)));
  test.observed.assign(bins, 0);
  for (const double z : sample) {
    const auto bin = std::upper_bound(test.edges.begin(), test.edges.end(), z) - test.edges.begin();
    ++test.observed[static_cast<std::size_t>(bin)];
  }
  test.expected = static_cast<double>(sample.size()) / static_cast<double>(bins);
  for (const std::size_t o : test.observed) {
    const double d = static_cast<double>(o) - test.expected;
    test.statistic += d * d / test.expected;
  }
  test.dof = bins - 1;
  test.p_value = chi_square_survival(test.statistic, test.dof);
  return test;
}

}  // namespace shockgas::compare
