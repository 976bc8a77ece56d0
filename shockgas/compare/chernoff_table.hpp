#pragma once
// ln g of chernoff.hpp, tabulated for laws that need g at many points (the
// cluster velocity law integrates products of g over the shock masses).
//
// Piecewise Chebyshev interpolation of ln g on panels of width 1/4 with 21
// Chebyshev-Lobatto points each, on [lo, hi]; outside that range the direct
// evaluation. The default range, [-11, 12], holds every argument of the laws'
// convolutions, g(mu/2 + u) g(mu/2 - u) with mu <= 12 and |u| <= 6
// (shock_mass_law.cpp): past 11, ln g < -880 and each such term is 0.0
// (tests/compare/test_law_tables.cpp). ln g is entire and close to a cubic
// (-(2/3) x^3 + ln 4x for x >> 1, 2^(1/3) a_1 |x| for x << -1), so degree 20 on
// a quarter gives it to rounding: measured against chernoff_log_g, the
// difference is below 1e-14 max(1, |ln g|), the direct evaluation's own
// rounding (tests/compare/test_cluster_velocity_law.cpp). Building costs 92 x 21 evaluations of ln g
// (~0.1 s); a look-up, one Clenshaw sum.
#include <span>
#include <vector>

namespace shockgas::compare {

class ChernoffLogGTable {
 public:
  // Computes the table (21 direct evaluations a panel). Throws InputError
  // unless lo < hi.
  explicit ChernoffLogGTable(double lo = -11.0, double hi = 12.0);
  // A table computed before: its range (hi as computed, a whole number of
  // panels past lo) and coefficients.
  ChernoffLogGTable(double lo, double hi, std::vector<double> coefficients);
  double log_g(double x) const;
  // log_g at each x, into out (as many): the same bits as one at a time, in
  // less time (the points' sums run side by side).
  void log_g(std::span<const double> x, std::span<double> out) const;
  double g(double x) const;
  double lo() const { return lo_; }
  double hi() const { return hi_; }
  const std::vector<double>& coefficients() const { return coefficients_; }

 private:
  bool panel_of(double x, double& t, const double*& c) const;
  double lo_, hi_;
  std::vector<double> coefficients_;  // Chebyshev coefficients, kTerms per panel
};

// One table on the default range shared by the laws: the build's (stored_law_tables.cpp).
const ChernoffLogGTable& chernoff_log_g_table();

}  // namespace shockgas::compare
