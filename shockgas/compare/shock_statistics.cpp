#include "shockgas/compare/shock_statistics.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "shockgas/compare/cluster_velocity_law.hpp"
#include "shockgas/compare/goodness_of_fit.hpp"
#include "shockgas/compare/shock_mass_law.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::compare {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// A chi-square bin must expect this many shocks (the usual rule for Pearson's
// approximation), and a z bin hold this many clusters over all realizations for
// its jackknife error to be a fair estimate of its spread.
constexpr double kLeastExpected = 5;
constexpr std::size_t kLeastClustersInZBin = 20;

std::vector<double> even_edges(double lo, double hi, std::size_t bins) {
  std::vector<double> e(bins + 1);
  for (std::size_t j = 0; j <= bins; ++j) e[j] = lo + (hi - lo) * static_cast<double>(j) / bins;
  return e;
}

// The bin of value in edges (half-open [e_j, e_(j+1))), or -1 outside.
std::ptrdiff_t bin_of(const std::vector<double>& edges, double value) {
  if (!(value >= edges.front()) || !(value < edges.back())) return -1;
  return std::upper_bound(edges.begin(), edges.end(), value) - edges.begin() - 1;
}

// Column means of the rows and their jackknife errors (NaN from one row). A
// bin empty in every row has no error either: the jackknife's 0 would claim
// an exact 0, where no cluster in R realizations says only that the
// expectation is small (an upper bound, not a value and an error).
void mean_and_error(std::vector<std::vector<double>> rows, BinnedStatistic& out) {
  const std::size_t bins = out.edges.size() - 1;
  std::vector<std::vector<double>> kept;
  for (auto& r : rows)
    if (!r.empty()) kept.push_back(std::move(r));
  out.value.assign(bins, kNaN);
  out.error.assign(bins, kNaN);
  if (kept.size() == 1) out.value = kept.front();
  if (kept.size() < 2) return;
  std::vector<bool> empty(bins, true);
  for (const auto& r : kept)
    for (std::size_t j = 0; j < bins; ++j) empty[j] = empty[j] && r[j] == 0;
  const LeaveOneOutMeans means(std::move(kept));
  const auto estimates = jackknife_components(means.rows(), [&](std::size_t out) { return means.mean(out); });
  for (std::size_t j = 0; j < bins; ++j)
    out.value[j] = estimates[j].value, out.error[j] = empty[j] ? kNaN : estimates[j].error;
}

JackknifeEstimate mean_estimate(const std::vector<double>& samples) {
  JackknifeEstimate e;
  e.samples = samples.size();
  double sum = 0;
  for (double s : samples) sum += s;
  e.value = sum / static_cast<double>(samples.size());
  e.error = kNaN;
  if (samples.size() < 2) return e;
  return jackknife(samples.size(), [&](std::size_t out) {
    return out == samples.size() ? e.value : (sum - samples[out]) / static_cast<double>(samples.size() - 1);
  });
}

// Pearson's chi-square of the counts summed over R realizations against R times
// the expectation, sparse bins merged: each group closes once it expects >= 5,
// a short last group joins the one before.
void test_counts(BinnedStatistic& s, const std::vector<double>& observed, std::size_t R) {
  std::vector<std::array<double, 2>> groups;  // observed, expected
  std::array<double, 2> open{0, 0};
  for (std::size_t j = 0; j < observed.size(); ++j) {
    open[0] += observed[j], open[1] += s.exact[j] * static_cast<double>(R);
    if (open[1] >= kLeastExpected) groups.push_back(open), open = {0, 0};
  }
  if (open[1] > 0 && !groups.empty())
    groups.back()[0] += open[0], groups.back()[1] += open[1];
  else if (open[1] > 0)
    groups.push_back(open);
  if (groups.size() < 2 || groups.front()[1] < kLeastExpected) return;
  double chi2 = 0;
  for (const auto& [o, e] : groups) chi2 += (o - e) * (o - e) / e;
  s.chi2 = chi2, s.dof = groups.size(), s.bins_tested = groups.size();
  s.p_value = chi_square_survival(chi2, s.dof);
}

// The chi-square of the bins' means against the exact law with their jackknife
// errors, over the bins holding >= kLeastClustersInZBin clusters.
void test_means(BinnedStatistic& s, const std::vector<std::size_t>& clusters_in_bin) {
  double chi2 = 0;
  std::size_t tested = 0;
  for (std::size_t j = 0; j < s.value.size(); ++j) {
    if (clusters_in_bin[j] < kLeastClustersInZBin || !(s.error[j] > 0)) continue;
    const double d = (s.value[j] - s.exact[j]) / s.error[j];
    chi2 += d * d, ++tested;
  }
  if (tested < 3) return;
  s.chi2 = chi2, s.dof = tested - 1, s.bins_tested = tested;
  s.p_value = chi_square_survival(chi2, s.dof);
}

double mean_velocity(const Bodies& b) {
  double m = 0, p = 0;
  for (std::size_t i = 0; i < b.size(); ++i) m += b.m[i], p += b.m[i] * b.v[i];
  return m > 0 ? p / m : 0.0;
}

void masses(const std::vector<Bodies>& runs, const StatisticsShape& shape, ShockStatistics& s) {
  const double particle = shape.mass / shape.N;
  double heaviest = 0;
  for (const Bodies& b : runs)
    for (double m : b.m) heaviest = std::max(heaviest, m / particle);
  s.mass.edges = doubling_mass_edges(heaviest);
  std::vector<std::vector<double>> rows;
  std::vector<double> observed(s.mass.edges.size() - 1, 0.0);
  for (const Bodies& b : runs) {
    std::vector<double> count(observed.size(), 0.0);
    for (double m : b.m)
      if (const auto j = bin_of(s.mass.edges, m / particle); j >= 0) count[j] += 1, observed[j] += 1;
    rows.push_back(std::move(count));
  }
  mean_and_error(rows, s.mass);
  if (!shape.white_noise_D) return;
  // The last bin takes every heavier shock too (none was seen there).
  std::vector<double> edges = s.mass.edges;
  const double a = std::cbrt(4 * *shape.white_noise_D * shape.t * shape.t), density = shape.N / shape.L;
  edges.back() = std::max(edges.back(), 13 * density * a);  // the law is 0 beyond mu = 12
  s.mass.exact = expected_shocks_in_mass_bins(edges, *shape.white_noise_D, shape.L, density, shape.t);
  // The bins span 1.5 particles to the law's cut-off: their sum is
  // expected_shocks_above(1.5, ...), without a second quadrature.
  s.count_exact = 0;
  for (double e : s.mass.exact) *s.count_exact += e;
  test_counts(s.mass, observed, runs.size());
}

void velocities(const std::vector<Bodies>& runs, const StatisticsShape& shape, ShockStatistics& s) {
  s.velocity.edges = even_edges(-kStatisticsZMax, kStatisticsZMax, kStatisticsZBins);
  const double width = 2 * kStatisticsZMax / kStatisticsZBins, scale = std::cbrt(shape.t);
  std::vector<std::size_t> clusters_in_bin(kStatisticsZBins, 0);
  std::vector<std::vector<double>> rows;
  for (const Bodies& b : runs) {
    const double U = mean_velocity(b);
    std::vector<double> density(kStatisticsZBins, 0.0);
    for (std::size_t i = 0; i < b.size(); ++i)
      if (const auto j = bin_of(s.velocity.edges, (b.v[i] - U) * scale); j >= 0)
        density[j] += b.m[i] / shape.mass / width, ++clusters_in_bin[j];
    rows.push_back(std::move(density));
  }
  mean_and_error(rows, s.velocity);
  if (!shape.white_noise_D) return;
  s.velocity.exact = cluster_law_on_bins(s.velocity.edges, *shape.white_noise_D);
  test_means(s.velocity, clusters_in_bin);
}

void spacings(const std::vector<Bodies>& runs, const StatisticsShape& shape, ShockStatistics& s) {
  s.spacing.edges = even_edges(0, kStatisticsSpacingMax, kStatisticsSpacingBins);
  const double width = kStatisticsSpacingMax / kStatisticsSpacingBins;
  std::vector<std::vector<double>> rows;
  for (const Bodies& b : runs) {
    std::vector<double> gaps;
    for (std::size_t i = 1; i < b.size(); ++i) gaps.push_back(b.x[i] - b.x[i - 1]);
    if (shape.ring && b.size() >= 2) gaps.push_back(b.x.front() + shape.L - b.x.back());
    if (gaps.empty()) {
      rows.emplace_back();
      continue;
    }
    double mean = 0;
    for (double g : gaps) mean += g / static_cast<double>(gaps.size());
    std::vector<double> density(kStatisticsSpacingBins, 0.0);
    for (double g : gaps)
      if (const auto j = bin_of(s.spacing.edges, g / mean); j >= 0)
        density[j] += 1.0 / static_cast<double>(gaps.size()) / width;
    rows.push_back(std::move(density));
  }
  mean_and_error(rows, s.spacing);
}

// Pearson's r of m and |v - U| from the sums over all clusters, each
// realization's sums apart so that the jackknife can leave one out.
void correlation(const std::vector<Bodies>& runs, ShockStatistics& s) {
  using Sums = std::array<double, 6>;  // n, m, m^2, w, w^2, m w
  std::vector<Sums> sums;
  Sums total{};
  for (const Bodies& b : runs) {
    const double U = mean_velocity(b);
    Sums k{};
    for (std::size_t i = 0; i < b.size(); ++i) {
      const double m = b.m[i], w = std::abs(b.v[i] - U);
      k[0] += 1, k[1] += m, k[2] += m * m, k[3] += w, k[4] += w * w, k[5] += m * w;
    }
    for (std::size_t c = 0; c < k.size(); ++c) total[c] += k[c];
    sums.push_back(k);
  }
  auto pearson = [&](std::size_t out) {
    Sums t = total;
    if (out < sums.size())
      for (std::size_t c = 0; c < t.size(); ++c) t[c] -= sums[out][c];
    const double n = t[0], cov = t[5] / n - t[1] / n * t[3] / n;
    const double var_m = t[2] / n - t[1] / n * t[1] / n, var_w = t[4] / n - t[3] / n * t[3] / n;
    return cov / std::sqrt(var_m * var_w);
  };
  if (runs.size() >= 2) {
    s.mass_speed_correlation = jackknife(runs.size(), pearson);
  } else {
    s.mass_speed_correlation.value = pearson(runs.size());
    s.mass_speed_correlation.error = kNaN;
    s.mass_speed_correlation.samples = runs.size();
  }
}

}  // namespace

std::vector<double> doubling_mass_edges(double heaviest) {
  std::vector<double> edges{1.5, 2.5};  // at least one bin, when no cluster is heavier than a particle
  for (double m = 4; edges.back() <= heaviest; m *= 2) edges.push_back(m + 0.5);
  return edges;
}

ShockStatistics shock_statistics(const std::vector<Bodies>& realizations, const StatisticsShape& shape) {
  require(!realizations.empty(), "stats.realizations", realizations.size(), ">= 1");
  for (const auto& [name, value] : {std::pair{"initial.N", shape.N},
                                    {"initial.mass", shape.mass},
                                    {"initial.L", shape.L},
                                    {"stats.t", shape.t}})
    require_above(name, value, 0.0);
  ShockStatistics s;
  s.shape = shape;
  s.realizations = realizations.size();
  std::vector<double> counts;
  for (const Bodies& b : realizations)
    counts.push_back(static_cast<double>(b.size())), s.clusters += b.size();
  s.count = mean_estimate(counts);
  masses(realizations, shape, s);
  velocities(realizations, shape, s);
  spacings(realizations, shape, s);
  correlation(realizations, s);
  return s;
}

}  // namespace shockgas::compare
