#pragma once
// Ring positions wrapped into one period (private to particles/): the recorder's
// rule, and the same rule without a division per body for streamed chains.
#include <cmath>
#include <limits>

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
