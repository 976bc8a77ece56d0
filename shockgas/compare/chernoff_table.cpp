#include "shockgas/compare/chernoff_table.hpp"

#include <cmath>
#include <numbers>
#include <string>
#include <utility>

#include "shockgas/compare/chernoff.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::compare {

namespace {

constexpr int kDegree = 20;
constexpr int kTerms = kDegree + 1;
constexpr double kPanel = 0.25;

// Chebyshev coefficients c_k of the interpolant through f at the Lobatto points
// t_j = cos(j pi / n) of [-1, 1] (discrete cosine transform, halved end terms).
std::vector<double> chebyshev_coefficients(const std::vector<double>& f) {
  const int n = kDegree;
  std::vector<double> c(kTerms, 0.0);
  for (int k = 0; k <= n; ++k) {
    double sum = 0;
    for (int j = 0; j <= n; ++j) {
      const double w = (j == 0 || j == n) ? 0.5 : 1.0;
      sum += w * f[j] * std::cos(std::numbers::pi * j * k / n);
    }
    c[k] = 2.0 * sum / n * ((k == 0 || k == n) ? 0.5 : 1.0);
  }
  return c;
}

}  // namespace

ChernoffLogGTable::ChernoffLogGTable(double lo, double hi) : lo_(lo), hi_(hi) {
  require(lo < hi, "chernoff_table.range", hi, "hi > lo");
  const int panels = static_cast<int>(std::ceil((hi - lo) / kPanel));
  hi_ = lo_ + panels * kPanel;
  for (int p = 0; p < panels; ++p) {
    const double mid = lo_ + (p + 0.5) * kPanel;
    std::vector<double> f(kTerms);
    for (int j = 0; j < kTerms; ++j)
      f[j] = chernoff_log_g(mid + 0.5 * kPanel * std::cos(std::numbers::pi * j / kDegree));
    const std::vector<double> c = chebyshev_coefficients(f);
    coefficients_.insert(coefficients_.end(), c.begin(), c.end());
  }
}

ChernoffLogGTable::ChernoffLogGTable(double lo, double hi, std::vector<double> coefficients)
    : lo_(lo), hi_(hi), coefficients_(std::move(coefficients)) {
  require(lo < hi, "chernoff_table.range", hi, "hi > lo");
  const auto panels = static_cast<std::size_t>(std::round((hi - lo) / kPanel));
  require(coefficients_.size() == panels * kTerms, "chernoff_table.coefficients", coefficients_.size(),
          std::to_string(panels * kTerms) + " (" + std::to_string(kTerms) + " for each of the " +
              std::to_string(panels) + " panels of [lo, hi])");
}

double ChernoffLogGTable::log_g(double x) const {
  if (!(x >= lo_ && x <= hi_)) return chernoff_log_g(x);
  const auto panels = static_cast<int>(coefficients_.size() / kTerms);
  const int p = std::min(panels - 1, static_cast<int>((x - lo_) / kPanel));
  const double t = (x - (lo_ + (p + 0.5) * kPanel)) / (0.5 * kPanel);  // in [-1, 1]
  const double* c = coefficients_.data() + static_cast<std::size_t>(p) * kTerms;
  double b1 = 0, b2 = 0;  // Clenshaw: sum_k c_k T_k(t)
  for (int k = kDegree; k >= 1; --k) {
    const double b0 = 2 * t * b1 - b2 + c[k];
    b2 = b1, b1 = b0;
  }
  return t * b1 - b2 + c[0];
}

double ChernoffLogGTable::g(double x) const { return std::exp(log_g(x)); }

}  // namespace shockgas::compare
