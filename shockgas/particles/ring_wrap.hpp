#pragma once
// Ring positions wrapped into one period (private to particles/): the recorder's
// rule, and the same rule without a division per body for streamed chains.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace shockgas::particles::detail {

// A ring position wrapped into [0, L): x - L floor(x / L), where a result that
// rounding leaves at L (or below 0) becomes 0.
inline double wrap_into(double x, double L) {
  const double w = x - L * std::floor(x / L);
  return w >= L || w < 0 ? 0.0 : w;
}

// wrap_into(x, L) for positions that mostly stay in one period, as the chain's
// do: the division and floor only when x leaves the period of the previous one.
// Inside [k L + e, (k + 1) L - e), e = 2^-40 L, floor(x / L) is k whatever the
// rounding of x / L (for |k| < 2^10; beyond, every x takes the division), and
// x - L k is the same expression: the result is wrap_into's, to the bit.
class PeriodWrap {
 public:
  explicit PeriodWrap(double L) : L_(L) {}
  double operator()(double x) {
    if (!(x >= lo_ && x < hi_)) enter(x);
    const double w = x - L_ * k_;
    return w >= L_ || w < 0 ? 0.0 : w;
  }

  // The period of x: operator()(y) for y in [lo, hi) is y - shift, or 0 where
  // that is >= L or < 0 (lo = +inf, hi = -inf when it holds no other position).
  struct Period {
    double lo = 0, hi = 0, shift = 0, L = 0;
  };
  Period period_of(double x) {
    if (!(x >= lo_ && x < hi_)) enter(x);
    return {lo_, hi_, L_ * k_, L_};
  }

  // w[k] = operator()(x[k]) for k < n: the expression of x[0]'s period for all,
  // two at a time, unless one lies outside it (then one by one).
  void wrap_all(const double* x, double* w, std::size_t n) {
    const double shift = period_of(x[0]).shift;
    std::size_t k = 0;
    bool inside = true;
#if defined(__SSE2__)
    const __m128d lo = _mm_set1_pd(lo_), hi = _mm_set1_pd(hi_), s = _mm_set1_pd(shift), L = _mm_set1_pd(L_);
    __m128d all = _mm_castsi128_pd(_mm_set1_epi64x(-1));
    for (; k + 2 <= n; k += 2) {
      const __m128d xk = _mm_loadu_pd(x + k);
      all = _mm_and_pd(all, _mm_and_pd(_mm_cmpge_pd(xk, lo), _mm_cmplt_pd(xk, hi)));
      const __m128d wk = _mm_sub_pd(xk, s);
      const __m128d off = _mm_or_pd(_mm_cmpge_pd(wk, L), _mm_cmplt_pd(wk, _mm_setzero_pd()));
      _mm_storeu_pd(w + k, _mm_andnot_pd(off, wk));
    }
    inside = _mm_movemask_pd(all) == 3;
#endif
    for (; k < n; ++k) {
      inside &= x[k] >= lo_ && x[k] < hi_;
      const double wk = x[k] - shift;
      w[k] = wk >= L_ || wk < 0 ? 0.0 : wk;
    }
    if (!inside)
      for (k = 0; k < n; ++k) w[k] = (*this)(x[k]);
  }

 private:
  void enter(double x) {
    k_ = std::floor(x / L_);
    const double e = 0x1p-40 * L_;
    const bool near = std::abs(k_) < 0x1p10;
    lo_ = near ? L_ * k_ + e : inf;
    hi_ = near ? L_ * (k_ + 1) - e : -inf;
  }
  static constexpr double inf = std::numeric_limits<double>::infinity();
  double L_, k_ = 0, lo_ = inf, hi_ = -inf;  // [lo_, hi_): x with floor(x / L) = k_; empty at first
};

}  // namespace shockgas::particles::detail
