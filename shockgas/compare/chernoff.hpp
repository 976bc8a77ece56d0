#pragma once
// Chernoff's distribution: the law of Z = argmax_s (W(s) - s^2) for a two-sided
// standard Brownian motion W (W(0) = 0). It is the law of the Eulerian velocity
// of Burgers turbulence from white-noise initial velocity
// (eulerian_velocity_law.hpp).
//
// Density (Groeneboom 1989, Probab. Th. Rel. Fields 81, 79; constants as in
// Groeneboom & Wellner 2001, J. Comput. Graph. Statist. 10, 388):
//     f(z) = g(z) g(-z) / 2,
// where g has the Fourier transform  int e^(i s x) g(x) dx = 2^(1/3) / Ai(i 2^(-1/3) s).
// Inverting the transform with u = i 2^(-1/3) s,
//     g(x) = 2^(2/3) / (2 pi i) int_{c - i inf}^{c + i inf} exp(-2^(1/3) x u) / Ai(u) du,    (1)
// for any c > a_1 (the largest zero of Ai; 1/Ai decays like exp(-(sqrt 2/3) |Im u|^(3/2))
// along every vertical line, so the path may move sideways freely between zeros).
// Moving the line left of a_1 picks up the residue at a_1:
//     g(x) = 2^(2/3) exp(-2^(1/3) a_1 x) / Ai'(a_1) + [(1) with a_2 < c < a_1].                (2)
// g(x) decays like exp(-(2/3) x^3) for x -> +inf (a saddle of (1) at u = 2^(2/3) x^2)
// and like exp(2^(1/3) a_1 |x|) for x -> -inf (the residue in (2)).
//
// Numerics (chernoff.cpp): for x >= 0, (1) on the vertical line through the
// saddle, c = max(2^(2/3) x^2, 1/2); for x < 0, (2) with c = (a_1 + a_2) / 2.
// The integrand is analytic in a strip about the line and decays faster than
// exponentially, so the trapezoidal rule converges exponentially in the step;
// Ai along the line comes from Taylor steps of Ai'' = u Ai upward from Ai(c), a
// direction in which Ai grows (stable). Measured against an mpmath evaluation of
// (1) on other lines at 40 digits: relative error of g below 3e-14 for -6 <= x <= 6
// (tests/compare/test_chernoff.cpp).
//
// Known values (Groeneboom & Wellner 2001, Table): E Z^2 = 0.2635596,
// P(Z <= 0.8450812) = 0.95, P(Z <= 1.1715343) = 0.99.
//
// Tail (derived in chernoff.cpp):
//     f(z) ~ C |z| exp(-(2/3)|z|^3 + 2^(1/3) a_1 |z|),   C = 2^(5/3) / Ai'(a_1) = 4.52760...,
// with relative corrections 1/(8|z|^3) - 1/(8|z|^6) + 175/(512|z|^9) + ... (the saddle)
// and (Ai'(a_1)/Ai'(a_k)) exp(2^(1/3) (a_k - a_1) |z|), k >= 2 (the further residues).
#include <cstddef>

namespace shockgas::compare {

// g(x) of (1) and ln g(x) (g > 0; ln g stays finite where g underflows, |x| >~ 9).
double chernoff_g(double x);
double chernoff_log_g(double x);

// f(z) and ln f(z).
double chernoff_density(double z);
double chernoff_log_density(double z);

// P(Z <= z) and P(Z > z) (the latter accurate to relative rounding in the upper tail),
// by Gauss-Legendre quadrature of f on panels of width <= 1/8: error < 1e-13.
double chernoff_cdf(double z);
double chernoff_survival(double z);

// int_a^b f (either order), by the same quadrature: for bins, cheaper than two CDFs.
double chernoff_integral(double a, double b);

// The p-quantile: P(Z <= q) = p. Throws InputError unless 0 < p < 1.
double chernoff_quantile(double p);

// C = 2^(5/3) / Ai'(a_1) and the leading tail C |z| exp(-(2/3)|z|^3 + 2^(1/3) a_1 |z|).
double chernoff_tail_constant();
double chernoff_tail(double z);

// The pieces of f = g(z) g(-z) / 2, exposed for tests of the numerics: the
// contour integral on the line Re u = c with trapezoidal step h, without
// residues, as exp(log_scale) * value.
struct ChernoffLineIntegral {
  double log_scale = 0;
  double value = 0;
  std::size_t nodes = 0;  // trapezoid nodes used (y >= 0)
};
ChernoffLineIntegral chernoff_line_integral(double x, double c, double h);

}  // namespace shockgas::compare
