#include "shockgas/compare/jackknife.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "shockgas/core/error.hpp"

namespace shockgas::compare {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The jackknife of one component from theta (all) and the leave-one-out values.
JackknifeEstimate combine(double all, const std::vector<double>& left_out) {
  JackknifeEstimate e;
  e.value = all;
  e.samples = left_out.size();
  const auto n = static_cast<double>(left_out.size());
  double mean = 0;
  for (const double x : left_out) {
    if (!std::isfinite(x)) ++e.failed;
    mean += x;
  }
  mean /= n;
  double ss = 0;
  for (const double x : left_out) ss += (x - mean) * (x - mean);
  e.error = e.failed > 0 ? kNaN : std::sqrt((n - 1) / n * ss);
  e.bias = e.failed > 0 ? kNaN : (n - 1) * (mean - all);
  return e;
}

}  // namespace

JackknifeEstimate jackknife(std::size_t n, const std::function<double(std::size_t)>& estimate) {
  require(n >= 2, "jackknife.realizations", n, "at least 2 realizations");
  std::vector<double> left_out(n);
  for (std::size_t i = 0; i < n; ++i) left_out[i] = estimate(i);
  return combine(estimate(n), left_out);
}

std::vector<JackknifeEstimate> jackknife_components(
    std::size_t n, const std::function<std::vector<double>(std::size_t)>& estimate) {
  require(n >= 2, "jackknife.realizations", n, "at least 2 realizations");
  const std::vector<double> all = estimate(n);
  std::vector<std::vector<double>> by_component(all.size(), std::vector<double>(n));
  for (std::size_t i = 0; i < n; ++i) {
    const std::vector<double> theta = estimate(i);
    require(theta.size() == all.size(), "jackknife.components", theta.size(),
            "as many components as the estimate on all realizations (" + std::to_string(all.size()) + ")");
    for (std::size_t j = 0; j < all.size(); ++j) by_component[j][i] = theta[j];
  }
  std::vector<JackknifeEstimate> out;
  out.reserve(all.size());
  for (std::size_t j = 0; j < all.size(); ++j) out.push_back(combine(all[j], by_component[j]));
  return out;
}

LeaveOneOutMeans::LeaveOneOutMeans(std::vector<std::vector<double>> rows) : rows_(std::move(rows)) {
  require(rows_.size() >= 2, "jackknife.realizations", rows_.size(), "at least 2 realizations");
  std::size_t columns = 0;
  for (const auto& row : rows_) columns = std::max(columns, row.size());
  sum_.assign(columns, 0.0);
  count_.assign(columns, 0.0);
  for (const auto& row : rows_)
    for (std::size_t k = 0; k < row.size(); ++k) sum_[k] += row[k], count_[k] += 1;
}

std::vector<double> LeaveOneOutMeans::sum(std::size_t leave_out) const {
  std::vector<double> s = sum_;
  if (leave_out < rows_.size())
    for (std::size_t k = 0; k < rows_[leave_out].size(); ++k) s[k] -= rows_[leave_out][k];
  return s;
}

std::vector<double> LeaveOneOutMeans::mean(std::size_t leave_out) const {
  std::vector<double> s = sum(leave_out), c = count_;
  if (leave_out < rows_.size())
    for (std::size_t k = 0; k < rows_[leave_out].size(); ++k) c[k] -= 1;
  std::vector<double> m;
  for (std::size_t k = 0; k < s.size() && c[k] > 0; ++k) m.push_back(s[k] / c[k]);
  return m;
}

}  // namespace shockgas::compare
