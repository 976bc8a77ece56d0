#include "shockgas/compare/statistics.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "shockgas/core/error.hpp"

namespace shockgas::compare {

double quantile(std::vector<double> values, double p) {
  require(!values.empty(), "quantile.values", values.size(), "at least one value");
  require(p >= 0 && p <= 1, "quantile.p", p, "0 <= p <= 1");
  std::sort(values.begin(), values.end());
  const double h = p * static_cast<double>(values.size() - 1);
  const std::size_t lo = static_cast<std::size_t>(std::floor(h));
  const std::size_t hi = std::min(lo + 1, values.size() - 1);
  return values[lo] + (h - static_cast<double>(lo)) * (values[hi] - values[lo]);
}

Quartiles quartiles(const std::vector<double>& values) {
  return Quartiles{quantile(values, 0.25), quantile(values, 0.5), quantile(values, 0.75)};
}

LineFit fit_line(std::span<const double> x, std::span<const double> y, std::span<const double> weights) {
  require(x.size() == y.size(), "fit_line.y", y.size(),
          "as many values as x (" + std::to_string(x.size()) + ")");
  require(weights.empty() || weights.size() == x.size(), "fit_line.weights", weights.size(),
          "empty or as many as x");
  std::vector<std::size_t> used;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double w = weights.empty() ? 1.0 : weights[i];
    require(w >= 0 && std::isfinite(w), "fit_line.weights", w, "finite, >= 0");
    if (w > 0) used.push_back(i);
  }
  require(used.size() >= 2, "fit_line.points", used.size(), "at least 2 points with weight > 0");
  const Eigen::Index n = static_cast<Eigen::Index>(used.size());
  Eigen::MatrixXd a(n, 2);
  Eigen::VectorXd b(n);
  double sum_w = 0;
  for (Eigen::Index k = 0; k < n; ++k) {
    const std::size_t i = used[static_cast<std::size_t>(k)];
    const double w = weights.empty() ? 1.0 : weights[i];
    const double s = std::sqrt(w);
    a(k, 0) = s;
    a(k, 1) = s * x[i];
    b(k) = s * y[i];
    sum_w += w;
  }
  const auto qr = a.colPivHouseholderQr();
  require(qr.rank() == 2, "fit_line.x", x[used[0]], "at least two distinct x values");
  const Eigen::Vector2d c = qr.solve(b);
  const double rss = (a * c - b).squaredNorm();
  LineFit fit;
  fit.intercept = c(0);
  fit.slope = c(1);
  fit.points = used.size();
  fit.rms_residual = std::sqrt(rss / sum_w);
  if (n > 2) {
    const double sigma2 = rss / static_cast<double>(n - 2);
    const Eigen::Matrix2d cov = sigma2 * (a.transpose() * a).inverse();
    fit.intercept_error = std::sqrt(cov(0, 0));
    fit.slope_error = std::sqrt(cov(1, 1));
  }
  return fit;
}

}  // namespace shockgas::compare
