#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "reference_table.hpp"
#include "shockgas/compare/airy.hpp"
#include "shockgas/compare/chernoff.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::compare {
namespace {

// int h sum_j F(j h) over the whole line. f is entire and decays like
// exp(-(2/3)|z|^3), so the trapezoidal rule converges faster than any power of h:
// an integration independent of the library's Gauss-Legendre panels.
double trapezoid_on_line(const std::function<double(double)>& F, double h) {
  double sum = F(0);
  for (int j = 1; j * h <= 6.0; ++j) sum += F(j * h) + F(-j * h);  // f(6) ~ 1e-70
  return h * sum;
}

double second_moment(double h) {
  return trapezoid_on_line([](double z) { return z * z * chernoff_density(z); }, h);
}

TEST(Chernoff, GAgreesWithMpmathAt40Digits) {
  // tests/compare/data/chernoff_g_reference.csv: (1) of chernoff.hpp on other
  // lines, with mpmath's Airy function and quadrature (scripts/reference/chernoff_reference.py).
  // Tolerance: 1e-13 relative; the conditioning of exp(-(2/3) x^3) alone is
  // 2 x^3 eps ~ 1e-13 at x = 6. Measured: 3e-14.
  const auto rows = testing::read_reference_table("chernoff_g_reference.csv");
  ASSERT_EQ(rows.size(), 25u);
  for (const auto& r : rows) EXPECT_NEAR(chernoff_g(r[0]) / r[1], 1.0, 1e-13) << "x = " << r[0];
}

TEST(Chernoff, TrapezoidStepOfTheContourIsConverged) {
  // Halving the step of the line integrals leaves them unchanged to rounding.
  for (double x : {0.0, 1.0, 3.0}) {
    const double c = std::max(std::cbrt(4.0) * x * x, 0.5);
    const ChernoffLineIntegral a = chernoff_line_integral(x, c, 0.2), b = chernoff_line_integral(x, c, 0.1);
    EXPECT_NEAR(a.value / b.value, 1.0, 1e-14) << x;
  }
  const double c = 0.5 * (airy_ai_zero(1).a + airy_ai_zero(2).a);
  const ChernoffLineIntegral a = chernoff_line_integral(-1.0, c, 0.1),
                             b = chernoff_line_integral(-1.0, c, 0.05);
  EXPECT_NEAR(std::exp(a.log_scale) * (a.value - b.value), 0.0, 1e-15 * chernoff_g(-1.0));
}

TEST(Chernoff, IntegratesToOneWithTheKnownVariance) {
  // Trapezoid on the line at h = 0.1 and 0.05: equal to ~1e-15, so the sum is
  // exact to rounding of ~100 terms (1e-14).
  const double norm = trapezoid_on_line(chernoff_density, 0.05);
  EXPECT_NEAR(trapezoid_on_line(chernoff_density, 0.1), norm, 1e-14);
  EXPECT_NEAR(norm, 1.0, 1e-13);
  // Groeneboom & Wellner (2001): E Z^2 = 0.2635596, rounded to 7 decimals: +-5e-8.
  EXPECT_NEAR(second_moment(0.1), second_moment(0.05), 1e-14);
  EXPECT_NEAR(second_moment(0.05), 0.2635596, 5e-8);
  // The library's own CDF (Gauss-Legendre) agrees: P(Z <= 0) = 1/2.
  EXPECT_NEAR(chernoff_cdf(0.0), 0.5, 1e-14);
}

TEST(Chernoff, QuantilesAsTabulated) {
  // Groeneboom & Wellner (2001): the 0.95 and 0.99 quantiles 0.8450812 and
  // 1.1715343, rounded to 7 decimals: +-5e-8 (ours: 0.84508119, 1.17153434).
  EXPECT_NEAR(chernoff_quantile(0.95), 0.8450812, 5e-8);
  EXPECT_NEAR(chernoff_quantile(0.99), 1.1715343, 5e-8);
  EXPECT_NEAR(chernoff_quantile(0.05), -chernoff_quantile(0.95), 1e-15);
  // The CDF at a quantile gives back p (Newton converged; GL panels to ~1e-15).
  EXPECT_NEAR(chernoff_cdf(chernoff_quantile(0.8)), 0.8, 1e-13);
  EXPECT_NEAR(chernoff_survival(2.5) + chernoff_cdf(2.5), 1.0, 1e-15);
  EXPECT_THROW(chernoff_quantile(1.0), InputError);
}

// The corrections to the leading tail derived in chernoff.cpp:
//   g(z) / (4 z e^{-2z^3/3}) = 1 + 1/(8z^3) - 1/(8z^6) + 175/(512 z^9) + ...   (saddle, z > 0)
//   g(-z) = 2^(2/3) sum_k e^{2^(1/3) a_k z} / Ai'(a_k)                           (residues, exact)
double saddle_series(double z, int terms) {
  const double u = 1 / (z * z * z);
  const double c[] = {1, 1.0 / 8, -1.0 / 8, 175.0 / 512};
  double s = 0;
  for (int k = terms - 1; k >= 0; --k) s = s * u + c[k];
  return s;
}
double residue_ratio(double z, int zeros) {  // sum over k <= zeros of the residues / the first
  const AiryZero a1 = airy_ai_zero(1);
  double s = 0;
  for (int k = 1; k <= zeros; ++k) {
    const AiryZero ak = airy_ai_zero(k);
    s += a1.aip / ak.aip * std::exp(std::cbrt(2.0) * (ak.a - a1.a) * z);
  }
  return s;
}

TEST(Chernoff, TailConstant) {
  // C = 2^(5/3) / Ai'(a_1) = 3.174802103936399 / 0.7012108227206915.
  EXPECT_NEAR(chernoff_tail_constant(), 4.527599975737, 1e-11);
}

TEST(Chernoff, TailFollowsTheAsymptoticForm) {
  for (double z = 2.0; z <= 3.5001; z += 0.25) {
    for (double sign : {1.0, -1.0}) {
      const double ratio = chernoff_density(sign * z) / chernoff_tail(sign * z);
      // Leading form: the deviation is bounded by its two first corrections,
      // 1/(8z^3) from the saddle and (Ai'(a_1)/|Ai'(a_2)|) e^{-2^(1/3)(a_1-a_2) z}
      // from the second zero (1.6e-2 + 1.1e-2 at z = 2; 2.9e-3 + 4e-4 at 3.5).
      const double first_corrections = 1 / (8 * z * z * z) + std::abs(residue_ratio(z, 2) - 1);
      EXPECT_LE(std::abs(ratio - 1), first_corrections) << "z = " << sign * z;
      // With the saddle series to z^-6 and the residues of five zeros (the sixth
      // adds < 1e-4 of what is left), what is left is the next saddle term
      // 175/(512 z^9): within twice that term. Measured: 0.66 of it at z = 2,
      // 0.91 at z = 3.5, tending to 1 as the coefficient 175/512 says.
      const double corrected = ratio / (saddle_series(z, 3) * residue_ratio(z, 5));
      EXPECT_LE(std::abs(corrected - 1), 2 * 175.0 / 512 / std::pow(z, 9)) << "z = " << sign * z;
    }
  }
}

}  // namespace
}  // namespace shockgas::compare
