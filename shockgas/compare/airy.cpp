// The Airy function of complex argument; see airy.hpp.
//
// Error analysis (eps = 2^-53 ~ 1.1e-16, relative errors of Ai):
//  * Taylor step (airy_step). With w(z0 + h s) = sum_n a_n s^n,
//        a_0 = w, a_1 = h w',  a_{n+2} = h^2 (z0 a_n + h a_{n-1}) / ((n+1)(n+2)),
//    summed until three consecutive terms fall below 1e-17 of the largest one
//    (the coefficients then decay at least geometrically, since the ratio
//    |h|^2 |z0| / n^2 -> 0). Rounding costs ~ eps sum_n |a_n| / |w(z0 + h)|,
//    a few eps for |h|^2 |z0| <~ 4 (paths below keep |h| sqrt(|z0|) <= 1.5),
//    except near a zero of w where only the absolute error is small.
//  * Maclaurin series, |z| <= 1: one step from 0. sum |terms| <= Ai(0) cosh-like
//    sums <= 0.7 while |Ai(z)| >= Ai(1) = 0.135 on |z| <= 1: a few eps.
//  * Paths, 1 < |z| < 9. Along a path errors are carried like any solution of
//    w'' = z w, and the solutions behave like exp(+-zeta). Stepping in the
//    direction in which |Ai| grows keeps the relative error at (steps) x eps:
//    inward from |z| = 9 in |arg z| < pi/3 (Ai ~ exp(-zeta) is recessive at
//    infinity there, so it grows inward), outward from |z| = 1 for
//    pi/3 <= |arg z| <= pi (Ai dominant or oscillatory). At most ~30 steps.
//  * Asymptotic expansion, |z| >= 9 (|zeta| >= 18), |arg z| <= 2 pi/3
//    (|ph zeta| <= pi): summed up to its least term, ~ exp(-2 |zeta|) <= 2.3e-16.
//    Olver's bounds (DLMF 9.7(iv)) put the remainder within a modest multiple of
//    the first neglected term, a multiple that grows toward |ph zeta| = pi.
//  * |z| >= 9, |arg z| > 2 pi/3: Ai(z) = -w Ai(w z) - w^2 Ai(w^2 z), both
//    arguments in |arg| <= 2 pi/3; the two terms are no larger than the
//    oscillation they add up to (no cancellation apart from the zeros).
//  * Beyond all this, the phase exp(-zeta) is only as good as zeta: |zeta| eps.
// Measured against SciPy (tests/compare/test_airy.cpp) on rings 0.3 <= |z| <= 40:
// error <= 37 eps (1 + |zeta|) of the envelope |Ai| + |Ai'| / |z|^(1/2), the
// worst on the positive real axis at z = 2 (the longest inward path).
#include "shockgas/compare/airy.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "shockgas/core/error.hpp"

namespace shockgas::compare {

namespace {

using cplx = std::complex<double>;

constexpr double kAi0 = 0.355028053887817239260;    // Ai(0) = 3^(-2/3) / Gamma(2/3)
constexpr double kAip0 = -0.258819403792806798405;  // Ai'(0) = -3^(-1/3) / Gamma(1/3)
constexpr double kMaclaurinRadius = 1.0;
constexpr double kAsymptoticRadius = 9.0;  // |zeta| >= 18: least term of the expansion ~ 2e-16
constexpr double kTwoPiOverThree = 2.0 * std::numbers::pi / 3.0;

AiryPair scale(AiryPair w, cplx factor) { return {w.ai * factor, w.aip * factor}; }

// Keeps z off the lower lip of the branch cut: a real z has imaginary part +0.
cplx upper_lip(cplx z) { return z.imag() == 0 ? cplx(z.real(), 0.0) : z; }

// (w, w') at `to` from (w, w') at `from`, by Taylor steps on the segment.
AiryPair step_along(cplx from, AiryPair w, cplx to) {
  const double r = std::max({1.0, std::abs(from), std::abs(to)});
  const double h_max = std::min(1.0, 1.5 / std::sqrt(r));
  const int steps = std::max(1, static_cast<int>(std::ceil(std::abs(to - from) / h_max)));
  const cplx h = (to - from) / static_cast<double>(steps);
  for (int k = 0; k < steps; ++k) w = airy_step(from + static_cast<double>(k) * h, w, h);
  return w;
}

AiryPair maclaurin(cplx z) { return airy_step(0.0, {kAi0, kAip0}, z); }

// exp(zeta) (Ai, Ai') by the asymptotic expansion (DLMF 9.7.5, 9.7.6):
//   Ai(z)  ~ exp(-zeta) / (2 sqrt(pi) z^(1/4)) sum_k (-1)^k u_k zeta^-k,
//   Ai'(z) ~ -z^(1/4) exp(-zeta) / (2 sqrt(pi)) sum_k (-1)^k v_k zeta^-k,
//   u_k = (6k-5)(6k-3)(6k-1) / ((2k-1) 216 k) u_{k-1},  v_k = -(6k+1)/(6k-1) u_k,
// summed up to the least term. For |z| >= 9 and |arg z| <= 2 pi / 3.
AiryPair asymptotic_scaled(cplx z) {
  const cplx inv_zeta = 1.0 / airy_zeta(z);
  cplx su = 1.0, sv = 1.0, power = 1.0;
  double u = 1.0, last = 1.0;
  for (int k = 1; k < 200; ++k) {
    u *= (6.0 * k - 5) * (6.0 * k - 3) * (6.0 * k - 1) / ((2.0 * k - 1) * 216.0 * k);
    power *= -inv_zeta;
    const cplx term = u * power;
    const double size = std::abs(term);
    if (size > last) break;  // the least term has passed
    su += term;
    sv += -(6.0 * k + 1) / (6.0 * k - 1) * term;
    last = size;
    if (size < 1e-17) break;
  }
  const cplx quarter = std::exp(0.25 * std::log(z));
  const double two_sqrt_pi = 2.0 * std::sqrt(std::numbers::pi);
  return {su / (two_sqrt_pi * quarter), -quarter * sv / two_sqrt_pi};
}

// exp(zeta) (Ai, Ai') for |z| >= 9 (Im z >= 0): the expansion, or the
// connection formula Ai(z) = -w Ai(wz) - w^2 Ai(w^2 z) (DLMF 9.2.12) and its
// derivative Ai'(z) = -w^2 Ai'(wz) - w Ai'(w^2 z) beyond arg z = 2 pi / 3.
AiryPair large_scaled(cplx z) {
  if (std::arg(z) <= kTwoPiOverThree) return asymptotic_scaled(z);
  const cplx w = std::polar(1.0, kTwoPiOverThree), w2 = w * w;
  const cplx z1 = w * z, z2 = w2 * z, zeta = airy_zeta(z);
  const AiryPair a1 = scale(asymptotic_scaled(z1), std::exp(zeta - airy_zeta(z1)));
  const AiryPair a2 = scale(asymptotic_scaled(z2), std::exp(zeta - airy_zeta(z2)));
  return {-w * a1.ai - w2 * a2.ai, -w2 * a1.aip - w * a2.aip};
}

// (Ai, Ai') for |z| < 9 (Im z >= 0), unscaled.
AiryPair moderate(cplx z) {
  const double r = std::abs(z);
  if (r <= kMaclaurinRadius) return maclaurin(z);
  if (std::arg(z) < std::numbers::pi / 3.0) {
    const cplx far = z * (kAsymptoticRadius / r);
    return step_along(far, scale(asymptotic_scaled(far), std::exp(-airy_zeta(far))), z);
  }
  const cplx near = z * (kMaclaurinRadius / r);
  return step_along(near, maclaurin(near), z);
}

AiryPair conjugate(AiryPair w) { return {std::conj(w.ai), std::conj(w.aip)}; }

}  // namespace

std::complex<double> airy_zeta(std::complex<double> z) {
  return (2.0 / 3.0) * std::exp(1.5 * std::log(upper_lip(z)));
}

AiryPair airy(std::complex<double> z) {
  z = upper_lip(z);
  if (z.imag() < 0) return conjugate(airy(std::conj(z)));  // Ai(conj z) = conj Ai(z)
  if (std::abs(z) < kAsymptoticRadius) return moderate(z);
  return scale(large_scaled(z), std::exp(-airy_zeta(z)));
}

AiryPair airy_scaled(std::complex<double> z) {
  z = upper_lip(z);
  if (z.imag() < 0) return conjugate(airy_scaled(std::conj(z)));
  if (std::abs(z) < kAsymptoticRadius) return scale(moderate(z), std::exp(airy_zeta(z)));
  return large_scaled(z);
}

AiryPair airy_step(std::complex<double> z0, AiryPair w, std::complex<double> h) {
  if (h == 0.0) return w;
  const cplx h2 = h * h, h2z0 = h2 * z0, h3 = h2 * h;
  cplx before = 0.0, current = w.ai, next = h * w.aip;  // a_{n-1}, a_n, a_{n+1}
  cplx value = current + next, slope = next;            // sum a_n, sum n a_n
  double largest = std::max(std::abs(current), std::abs(next));
  for (int n = 0, small = 0; n < 400 && small < 3; ++n) {
    const cplx after = (h2z0 * current + h3 * before) / ((n + 1.0) * (n + 2.0));
    value += after;
    slope += (n + 2.0) * after;
    const double size = std::abs(after) * (n + 2.0);
    largest = std::max(largest, size);
    small = size <= 1e-17 * largest ? small + 1 : 0;
    before = current, current = next, next = after;
  }
  return {value, slope / h};
}

AiryZero airy_ai_zero(int k) {
  require(k >= 1 && k <= 1000, "airy.zero_index", k, "1 <= k <= 1000");
  // a_k ~ -T(3 pi (4k - 1) / 8), T(t) = t^(2/3) (1 + 5/48 t^-2 - 5/36 t^-4) (DLMF 9.9.6, 9.9.18).
  const double t = 3.0 * std::numbers::pi * (4.0 * k - 1.0) / 8.0, t2 = 1.0 / (t * t);
  double a = -std::pow(t, 2.0 / 3.0) * (1.0 + t2 * (5.0 / 48.0 - t2 * 5.0 / 36.0));
  AiryPair w = airy(a);
  for (int iteration = 0; iteration < 20; ++iteration) {
    const double step = w.ai.real() / w.aip.real();
    a -= step;
    w = airy(a);
    if (std::abs(step) <= 4e-16 * std::abs(a)) break;
  }
  return {a, w.aip.real()};
}

}  // namespace shockgas::compare
