// Chernoff's distribution; see chernoff.hpp.
//
// The tail constant. For x -> +inf the integrand of (1) is, with k = 2^(1/3) and
// 1/Ai(u) ~ 2 sqrt(pi) u^(1/4) exp(zeta) (1 + (5/72)/zeta + ...), zeta = (2/3) u^(3/2),
//     exp(phi(u)) 2 sqrt(pi) u^(1/4),   phi(u) = -k x u + (2/3) u^(3/2).
// phi'(u) = -k x + u^(1/2) = 0 at u_s = k^2 x^2, phi(u_s) = -2 x^3 + (4/3) x^3 = -(2/3) x^3,
// phi''(u_s) = 1 / (2 k x) > 0 along the real axis, so the line Re u = u_s crosses
// the saddle in its direction of steepest descent. With u = u_s + i y, du = i dy,
//     g(x) ~ 2^(2/3)/(2 pi) 2 sqrt(pi) u_s^(1/4) exp(-(2/3) x^3) sqrt(2 pi / phi''(u_s))
//          = 2^(2/3)/(2 pi) 2 sqrt(pi) 2^(1/6) x^(1/2) 2 sqrt(pi) 2^(1/6) x^(1/2) exp(-(2/3) x^3)
//          = 4 x exp(-(2/3) x^3).
// Carrying Laplace's method to higher orders (scaling u = u_s w, the exponent is
// x^3 (-2w + (4/3) w^(3/2)), the amplitude w^(1/4) / sum_k (-1)^k u_k ((4/3) x^3 w^(3/2))^-k;
// the moments of the Gaussian in the steepest-descent variable give each order):
//     g(x) = 4 x exp(-(2/3) x^3) (1 + 1/(8 x^3) - 1/(8 x^6) + 175/(512 x^9) + O(x^-12)).
// For x -> -inf, (2) with every residue, exact:
//     g(x) = 2^(2/3) sum_k exp(2^(1/3) a_k |x|) / Ai'(a_k)  (x < 0),
// led by k = 1. Hence, f even,
//     f(z) = g(|z|) g(-|z|) / 2 ~ (2^(5/3) / Ai'(a_1)) |z| exp(-(2/3)|z|^3 + 2^(1/3) a_1 |z|),
// C = 2^(5/3) / Ai'(a_1) = 3.1748021 / 0.7012108 = 4.5276... (Groeneboom & Wellner 2001
// write the same constant as 4^(4/3) / (2 Ai'(a_1))).
#include "shockgas/compare/chernoff.hpp"

#include <cmath>
#include <complex>
#include <limits>
#include <numbers>

#include "shockgas/compare/airy.hpp"
#include "shockgas/compare/gauss_legendre.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::compare {

namespace {

const double kCbrt2 = std::cbrt(2.0);   // k = 2^(1/3)
const double kCbrt4 = kCbrt2 * kCbrt2;  // 2^(2/3)
constexpr double kMinLine = 0.5;        // Re u of the line for small x >= 0
constexpr double kStepRight = 0.2;      // trapezoid step on lines with c >= 1/2
constexpr double kStepLeft = 0.1;       // ... on the line between a_2 and a_1 (nearer the zeros)
constexpr double kNegligible = 1e-18;   // integrand / its largest value where the sum stops
constexpr std::size_t kMaxNodes = 100000;

// ln |Ai(c)| and Ai'(c) / Ai(c) at a real c (c > a_1 or between zeros).
struct RealAiry {
  double log_abs, sign, log_derivative;
};
RealAiry real_airy(double c) {
  if (c > 0) {  // Ai(c) = airye(c) exp(-zeta(c)), zeta real
    const AiryPair s = airy_scaled(c);
    return {std::log(s.ai.real()) - airy_zeta(c).real(), 1.0, s.aip.real() / s.ai.real()};
  }
  const AiryPair w = airy(c);
  return {std::log(std::abs(w.ai.real())), w.ai.real() < 0 ? -1.0 : 1.0, w.aip.real() / w.ai.real()};
}

const AiryZero& zero(int k) {
  static const AiryZero first = airy_ai_zero(1), second = airy_ai_zero(2);
  return k == 1 ? first : second;
}

// 2^(2/3) exp(-k x a_1) / Ai'(a_1): the residue term of (2).
double leading_residue(double x) { return kCbrt4 * std::exp(-kCbrt2 * x * zero(1).a) / zero(1).aip; }

double line_for(double x) { return std::max(kCbrt4 * x * x, kMinLine); }

double between_first_zeros() { return 0.5 * (zero(1).a + zero(2).a); }

// int_a^b f by Gauss-Legendre on panels of width <= 1/8.
double integrate_density(double a, double b) {
  static const GaussRule rule = gauss_legendre(16);
  const int panels = std::max(1, static_cast<int>(std::ceil(std::abs(b - a) * 8.0)));
  const double width = (b - a) / panels;
  double sum = 0;
  for (int p = 0; p < panels; ++p) {
    const double mid = a + (p + 0.5) * width;
    for (std::size_t i = 0; i < rule.x.size(); ++i)
      sum += rule.w[i] * chernoff_density(mid + 0.5 * width * rule.x[i]);
  }
  return 0.5 * width * sum;
}

// Where the upper tail beyond z >= 0 is below e^-50 of the tail at z.
double tail_end(double z) { return std::cbrt(z * z * z + 75.0) + 0.5; }

}  // namespace

ChernoffLineIntegral chernoff_line_integral(double x, double c, double h) {
  require_above("chernoff.step", h, 0.0);
  // exp(-k x u) / Ai(u) = [exp(-k x c) / Ai(c)] exp(-i k x y) / w(u),  w = Ai / Ai(c).
  const RealAiry start = real_airy(c);
  AiryPair w{1.0, start.log_derivative};
  double sum = 0.5, largest = 1.0;  // y = 0 carries weight 1/2
  std::size_t node = 1;
  for (int quiet = 0; quiet < 3; ++node) {
    if (node > kMaxNodes) throw RunError("chernoff: the contour integral did not converge");
    const double y = static_cast<double>(node) * h;
    w = airy_step({c, y - h}, w, {0.0, h});
    const std::complex<double> term = std::polar(1.0, -kCbrt2 * x * y) / w.ai;
    sum += term.real();
    largest = std::max(largest, std::abs(term));
    quiet = std::abs(term) < kNegligible * largest ? quiet + 1 : 0;
  }
  return {-kCbrt2 * x * c - start.log_abs, start.sign * kCbrt4 / std::numbers::pi * h * sum, node};
}

double chernoff_log_g(double x) {
  if (x >= 0) {
    const ChernoffLineIntegral line = chernoff_line_integral(x, line_for(x), kStepRight);
    return line.log_scale + std::log(line.value);
  }
  const ChernoffLineIntegral line = chernoff_line_integral(x, between_first_zeros(), kStepLeft);
  return std::log(leading_residue(x) + std::exp(line.log_scale) * line.value);
}

double chernoff_g(double x) { return std::exp(chernoff_log_g(x)); }

double chernoff_log_density(double z) {
  const double a = std::abs(z);
  return std::log(0.5) + chernoff_log_g(a) + chernoff_log_g(-a);
}

double chernoff_density(double z) { return std::exp(chernoff_log_density(z)); }

double chernoff_integral(double a, double b) { return integrate_density(a, b); }

double chernoff_survival(double z) {
  if (z < 0) return 1.0 - chernoff_survival(-z);
  return integrate_density(z, tail_end(z));
}

double chernoff_cdf(double z) {
  if (z > 0) return 1.0 - chernoff_survival(z);
  return chernoff_survival(-z);
}

double chernoff_quantile(double p) {
  require(p > 0 && p < 1, "chernoff.p", p, "0 < p < 1");
  if (p < 0.5) return -chernoff_quantile(1.0 - p);
  // Newton on S(q) = 1 - p from q = 0 (S(0) = 1/2), carrying S along by the
  // integral of f between iterates; S is convex for q >= 0, so Newton from
  // the left never overshoots the root.
  const double target = 1.0 - p;
  double q = 0, s = 0.5;
  for (int iteration = 0; iteration < 60; ++iteration) {
    const double step = (s - target) / chernoff_density(q);
    if (!(std::abs(step) > 1e-15 * std::max(1.0, q))) break;
    s -= integrate_density(q, q + step);
    q += step;
  }
  return q;
}

double chernoff_tail_constant() { return std::pow(2.0, 5.0 / 3.0) / zero(1).aip; }

double chernoff_tail(double z) {
  const double a = std::abs(z);
  return chernoff_tail_constant() * a * std::exp(-2.0 / 3.0 * a * a * a + kCbrt2 * zero(1).a * a);
}

}  // namespace shockgas::compare
