#pragma once
// ln g of chernoff.hpp, tabulated for laws that need g at many points (the
// cluster velocity law integrates products of g over the shock masses).
//
// Piecewise Chebyshev interpolation of ln g on panels of width 1/4 with 21
// Chebyshev-Lobatto points each, on [lo, hi] (default [-11, 11]); outside that
// range the direct evaluation. ln g is entire and close to a cubic
// (-(2/3) x^3 + ln 4x for x >> 1, 2^(1/3) a_1 |x| for x << -1), so degree 20 on
// a quarter gives it to rounding: measured against chernoff_log_g, the
// difference is below 1e-14 max(1, |ln g|), the direct evaluation's own
// rounding (tests/compare/test_cluster_velocity_law.cpp). Building costs 88 x 21 evaluations of ln g
// (~0.1 s); a look-up, one Clenshaw sum.
#include <vector>

namespace shockgas::compare {

class ChernoffLogGTable {
 public:
  // Throws InputError unless lo < hi.
  explicit ChernoffLogGTable(double lo = -11.0, double hi = 11.0);
  double log_g(double x) const;
  double g(double x) const;

 private:
  double lo_, hi_;
  std::vector<double> coefficients_;  // Chebyshev coefficients, kTerms per panel
};

// One table shared by the laws, built on first use (thread-safe).
const ChernoffLogGTable& chernoff_log_g_table();

}  // namespace shockgas::compare
