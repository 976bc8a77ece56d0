#pragma once
// Slope limiters of the second-order (MUSCL) reconstruction. Given the backward
// and forward differences a = u_i - u_{i-1}, b = u_{i+1} - u_i, each returns the
// limited slope (times dx) of cell i: 0 at an extremum (a b <= 0), otherwise a
// value between min(|a|, |b|) and 2 min(|a|, |b|) with the sign of a and b, which
// keeps the scheme TVD (Sweby, SIAM J. Numer. Anal. 21, 995 (1984): the limiter
// function phi(r) = slope / b lies in 0 <= phi <= min(2 r, 2)). LeVeque 2002, §6.9-6.12.
#include <cmath>

#include "shockgas/continuum/params.hpp"

namespace shockgas::continuum {

// The most diffusive TVD limiter: the smaller difference.
struct MinmodLimiter {
  static double slope(double a, double b) {
    if (a * b <= 0) return 0.0;
    return std::abs(a) < std::abs(b) ? a : b;
  }
};

// van Leer's harmonic mean 2 a b / (a + b).
struct VanLeerLimiter {
  static double slope(double a, double b) {
    const double ab = a * b;
    return ab > 0 ? 2 * ab / (a + b) : 0.0;
  }
};

// Monotonised central (van Leer 1977): minmod of the central difference (a + b)/2,
// 2 a and 2 b.
struct McLimiter {
  static double slope(double a, double b) {
    if (a * b <= 0) return 0.0;
    const double m = std::fmin(std::fmin(2 * std::abs(a), 2 * std::abs(b)), 0.5 * std::abs(a + b));
    return a > 0 ? m : -m;
  }
};

// Calls fn(MinmodLimiter{}) etc.: one dispatch per run, the limiter inlined in the loops.
template <class Fn>
decltype(auto) with_limiter(Limiter limiter, Fn&& fn) {
  switch (limiter) {
    case Limiter::minmod:
      return fn(MinmodLimiter{});
    case Limiter::vanleer:
      return fn(VanLeerLimiter{});
    case Limiter::mc:
      break;
  }
  return fn(McLimiter{});
}

}  // namespace shockgas::continuum
