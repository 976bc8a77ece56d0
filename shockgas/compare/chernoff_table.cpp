#include "shockgas/compare/chernoff_table.hpp"

#if defined(__AVX2__)
#include <immintrin.h>
#endif

#include <algorithm>
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
  require(panels >= 1, "chernoff_table.range", hi,
          "hi >= lo + " + std::to_string(kPanel / 2) + " (one panel)");
  require(coefficients_.size() == panels * kTerms, "chernoff_table.coefficients", coefficients_.size(),
          std::to_string(panels * kTerms) + " (" + std::to_string(kTerms) + " for each of the " +
              std::to_string(panels) + " panels of [lo, hi])");
}

// x's panel of the table and its place t in [-1, 1] there; false past the table.
bool ChernoffLogGTable::panel_of(double x, double& t, const double*& c) const {
  if (!(x >= lo_ && x <= hi_)) return false;
  const auto panels = static_cast<int>(coefficients_.size() / kTerms);
  const int p = std::min(panels - 1, static_cast<int>((x - lo_) / kPanel));
  t = (x - (lo_ + (p + 0.5) * kPanel)) / (0.5 * kPanel);
  c = coefficients_.data() + static_cast<std::size_t>(p) * kTerms;
  return true;
}

double ChernoffLogGTable::log_g(double x) const {
  double t = 0;
  const double* c = nullptr;
  if (!panel_of(x, t, c)) return chernoff_log_g(x);
  double b1 = 0, b2 = 0;  // Clenshaw: sum_k c_k T_k(t)
  for (int k = kDegree; k >= 1; --k) {
    const double b0 = 2 * t * b1 - b2 + c[k];
    b2 = b1, b1 = b0;
  }
  return t * b1 - b2 + c[0];
}

// Clenshaw's sum_k c_k T_k(t) is a chain of dependent operations (about 240
// cycles of latency for degree 20): up to kLanes points run side by side, each
// with the operations of one point alone, so their chains overlap and each
// result has the same bits as alone.
void ChernoffLogGTable::log_g(std::span<const double> x, std::span<double> out) const {
  if (out.size() !=
      x.size())  // the message built only when it is needed: this runs per panel of a quadrature
    throw InputError("chernoff_table.out", std::to_string(out.size()),
                     "as many values as arguments (" + std::to_string(x.size()) + ")");
  constexpr std::size_t kLanes = 8;
  for (std::size_t first = 0; first < x.size(); first += kLanes) {
    const std::size_t lanes = std::min(kLanes, x.size() - first);
    // Every lane runs (those past the points and past the table on t = 0 and
    // panel 0, their sums unused): loops of a fixed length, held in registers.
    double t[kLanes] = {}, b1[kLanes] = {}, b2[kLanes] = {};
    const double* c[kLanes];
    bool direct[kLanes];
    for (std::size_t j = 0; j < kLanes; ++j) {
      c[j] = coefficients_.data();  // a table has at least one panel
      direct[j] = true;
      if (j >= lanes) continue;
      if (panel_of(x[first + j], t[j], c[j]))
        direct[j] = false;
      else
        out[first + j] = chernoff_log_g(x[first + j]);
    }
#if defined(__AVX2__)
    // Four lanes to a vector, each lane the scalar operations below (IEEE
    // operations lane by lane, no contraction): the same bits.
    const __m256d two = _mm256_set1_pd(2.0);
    __m256d tv[2], b1v[2], b2v[2];
    for (std::size_t h = 0; h < 2; ++h)
      tv[h] = _mm256_loadu_pd(t + 4 * h), b1v[h] = _mm256_setzero_pd(), b2v[h] = _mm256_setzero_pd();
    for (int k = kDegree; k >= 1; --k)
      for (std::size_t h = 0; h < 2; ++h) {
        const double* const* ch = c + 4 * h;
        const __m256d ck = _mm256_set_pd(ch[3][k], ch[2][k], ch[1][k], ch[0][k]);
        const __m256d b0 =
            _mm256_add_pd(_mm256_sub_pd(_mm256_mul_pd(_mm256_mul_pd(two, tv[h]), b1v[h]), b2v[h]), ck);
        b2v[h] = b1v[h], b1v[h] = b0;
      }
    for (std::size_t h = 0; h < 2; ++h)
      _mm256_storeu_pd(b1 + 4 * h, b1v[h]), _mm256_storeu_pd(b2 + 4 * h, b2v[h]);
#else
    for (int k = kDegree; k >= 1; --k)
      for (std::size_t j = 0; j < kLanes; ++j) {
        const double b0 = 2 * t[j] * b1[j] - b2[j] + c[j][k];
        b2[j] = b1[j], b1[j] = b0;
      }
#endif
    for (std::size_t j = 0; j < lanes; ++j)
      if (!direct[j]) out[first + j] = t[j] * b1[j] - b2[j] + c[j][0];
  }
}

double ChernoffLogGTable::g(double x) const { return std::exp(log_g(x)); }

}  // namespace shockgas::compare
