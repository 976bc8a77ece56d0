#pragma once
// The Airy function Ai of complex argument, its derivative and its zeros: what
// the exact laws of Burgers turbulence from white noise are made of (Chernoff's
// distribution, chernoff.hpp). Neither the C++ library nor GSL has Ai(z) for
// complex z.
//
// Ai is the solution of w'' = z w that decays along the positive real axis,
// Ai(0) = 3^(-2/3) / Gamma(2/3), Ai'(0) = -3^(-1/3) / Gamma(1/3) (DLMF 9.2).
// Three ways to evaluate it, each where it is accurate (airy.cpp gives the
// error analysis; measured against SciPy's scipy.special.airy, the error is
// below 37 eps (1 + |zeta|) of |Ai| + |Ai'| / |z|^(1/2), i.e. ~1e-14 relative
// away from the zeros for |z| <~ 10):
//  * |z| <= 1: the Maclaurin series (a Taylor step of the ODE from 0);
//  * |z| >= 9, |arg z| <= 2 pi / 3: the asymptotic expansion (DLMF 9.7.5-6);
//    |z| >= 9, |arg z| > 2 pi / 3: Ai(z) = -w Ai(w z) - w^2 Ai(w^2 z),
//    w = exp(2 pi i / 3) (DLMF 9.2.12), both terms from the expansion;
//  * 1 < |z| < 9: Taylor steps of w'' = z w along the ray through z, in the
//    direction in which Ai grows (so that rounding errors do not grow faster
//    than Ai): inward from |z| = 9 when |arg z| < pi / 3, outward from |z| = 1
//    otherwise.
#include <complex>

namespace shockgas::compare {

struct AiryPair {
  std::complex<double> ai;   // Ai(z) (or a multiple of it: see airy_scaled, airy_step)
  std::complex<double> aip;  // Ai'(z), with the same factor
};

// Ai(z) and Ai'(z). Underflows or overflows where |Ai| leaves the range of
// double (|Re zeta| >~ 700, see airy_zeta); airy_scaled does not.
AiryPair airy(std::complex<double> z);

// exp(zeta) Ai(z) and exp(zeta) Ai'(z), zeta = (2/3) z^(3/2) (principal
// branch): finite for every z with |arg z| < pi (scipy.special.airye).
AiryPair airy_scaled(std::complex<double> z);

// zeta = (2/3) z^(3/2), principal branch.
std::complex<double> airy_zeta(std::complex<double> z);

// One step of the Airy equation w'' = z w: given any solution's (w, w') at z0,
// its (w, w') at z0 + h, by the Taylor series of w about z0 summed to rounding.
// Accurate for |h| <~ 1 / max(1, |z0|^(1/2)) (a few terms then suffice).
AiryPair airy_step(std::complex<double> z0, AiryPair w, std::complex<double> h);

// The k-th zero a_k of Ai (k >= 1; a_1 = -2.33810741..., a_k -> -infinity)
// and Ai'(a_k), to rounding (Newton from the asymptotic form, DLMF 9.9.6).
struct AiryZero {
  double a = 0;    // a_k
  double aip = 0;  // Ai'(a_k); sign (-1)^(k-1)
};
// Throws InputError unless 1 <= k <= 1000.
AiryZero airy_ai_zero(int k);

}  // namespace shockgas::compare
