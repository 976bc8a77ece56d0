#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <vector>

#include "shockgas/compare/cooling_law.hpp"
#include "shockgas/compare/jackknife.hpp"
#include "shockgas/compare/realization_errors.hpp"
#include "shockgas/core/error.hpp"
#include "shockgas/core/random.hpp"

namespace shockgas::compare {
namespace {

double mean_without(const std::vector<double>& x, std::size_t leave_out) {
  double s = 0, n = 0;
  for (std::size_t i = 0; i < x.size(); ++i)
    if (i != leave_out) s += x[i], n += 1;
  return s / n;
}

TEST(Jackknife, OfTheMeanIsTheStandardError) {
  // For the mean the jackknife is exact algebra: error = s / sqrt(n), bias 0.
  Rng rng(7);
  std::vector<double> x(37);
  for (double& v : x) v = 3 + 2 * rng.normal();
  const double n = static_cast<double>(x.size());
  const double m = std::accumulate(x.begin(), x.end(), 0.0) / n;
  double ss = 0;
  for (const double v : x) ss += (v - m) * (v - m);
  const JackknifeEstimate e = jackknife(x.size(), [&](std::size_t i) { return mean_without(x, i); });
  EXPECT_DOUBLE_EQ(e.value, m);
  EXPECT_NEAR(e.error, std::sqrt(ss / (n - 1) / n), 1e-14);
  EXPECT_NEAR(e.bias, 0.0, 1e-13);
  EXPECT_EQ(e.samples, x.size());
  EXPECT_EQ(e.failed, 0u);
}

TEST(Jackknife, RemovesTheFirstOrderBiasOfAPlugInVariance) {
  // The plug-in variance (1/n) sum (x - m)^2 has bias -s^2/n; its jackknife
  // bias-corrected value is exactly the unbiased s^2 (Efron & Tibshirani 1993, 10.3).
  Rng rng(11);
  std::vector<double> x(25);
  for (double& v : x) v = rng.uniform(-1, 1);
  auto plug_in = [&](std::size_t leave_out) {
    const double m = mean_without(x, leave_out);
    double ss = 0, n = 0;
    for (std::size_t i = 0; i < x.size(); ++i)
      if (i != leave_out) ss += (x[i] - m) * (x[i] - m), n += 1;
    return ss / n;
  };
  const JackknifeEstimate e = jackknife(x.size(), plug_in);
  const double n = static_cast<double>(x.size());
  EXPECT_NEAR(e.value - e.bias, e.value * n / (n - 1), 1e-14);
}

TEST(Jackknife, ComponentsAndLeaveOneOutMeansOfRaggedRows) {
  // Rows of different lengths (a realization that stopped early): column k is
  // the mean of the rows that reach it; leaving the only long row out drops the column.
  const LeaveOneOutMeans m({{1, 2, 3}, {3, 4}, {5, 6}});
  EXPECT_EQ(m.mean(3), (std::vector<double>{3, 4, 3}));
  EXPECT_EQ(m.mean(0), (std::vector<double>{4, 5}));
  EXPECT_EQ(m.mean(1), (std::vector<double>{3, 4, 3}));
  EXPECT_EQ(m.sum(2), (std::vector<double>{4, 6, 3}));
  const auto e = jackknife_components(3, [&](std::size_t i) {
    const auto v = m.mean(i);
    return std::vector<double>{v[0], v[1]};
  });
  ASSERT_EQ(e.size(), 2u);
  EXPECT_NEAR(e[0].error, std::sqrt(4.0 / 3.0), 1e-14);  // s/sqrt(n) of {1, 3, 5}
  EXPECT_THROW(LeaveOneOutMeans(std::vector<std::vector<double>>{{1.0}}), InputError);
  EXPECT_THROW(jackknife(1, [](std::size_t) { return 0.0; }), InputError);
  const JackknifeEstimate nan = jackknife(3, [](std::size_t i) { return i == 1 ? std::nan("") : 1.0; });
  EXPECT_EQ(nan.failed, 1u);
  EXPECT_TRUE(std::isnan(nan.error));
}

// Realizations of T(t) = t^(-2/3) exp(eps(t)) at K log-spaced times, eps a random
// walk over the sample index with steps of standard deviation s: later samples
// carry the earlier ones' noise, as T at 10^4 and 2 10^4 share a history.
std::vector<std::vector<double>> correlated_series(Rng& rng, std::size_t R, const std::vector<double>& t,
                                                   double s) {
  std::vector<std::vector<double>> rows(R);
  for (auto& row : rows) {
    double eps = 0;
    for (const double ti : t)
      eps += s * rng.normal(), row.push_back(std::pow(ti, -2.0 / 3.0) * std::exp(eps));
  }
  return rows;
}

TEST(Jackknife, ExponentErrorOfCorrelatedSeriesMatchesTheirTrueSpread) {
  // The known answer. To first order in s, ln <T> = -2/3 ln t + mean_i eps_i, so
  // the fitted exponent is -2/3 + sum_k c_k mean_i eps_i(t_k), c_k = (x_k - xbar) / Sxx
  // (x = ln t), with variance c^T C c / R, C_kl = s^2 min(k + 1, l + 1). The
  // jackknife over R realizations estimates that variance without bias for a
  // linear statistic; here the statistic is linear to O(s) = 1%.
  const std::size_t R = 10, K = 20, M = 400;
  const double s = 0.01;
  std::vector<double> t(K), x(K);
  for (std::size_t k = 0; k < K; ++k)
    t[k] = 1e4 * std::pow(10.0, static_cast<double>(k) / (K - 1)), x[k] = std::log(t[k]);
  const double xbar = std::accumulate(x.begin(), x.end(), 0.0) / K;
  double sxx = 0;
  for (const double v : x) sxx += (v - xbar) * (v - xbar);
  double var = 0;
  for (std::size_t k = 0; k < K; ++k)
    for (std::size_t l = 0; l < K; ++l)
      var += (x[k] - xbar) * (x[l] - xbar) / (sxx * sxx) * s * s * static_cast<double>(std::min(k, l) + 1);
  var /= R;
  Rng rng(2024);
  double jack_var = 0, fit_var = 0;
  for (std::size_t rep = 0; rep < M; ++rep) {
    const auto rows = correlated_series(rng, R, t, s);
    const JackknifeEstimate e = jackknife_T_exponent(t, rows, 1e4, 1e5);
    jack_var += e.error * e.error / M;
    const std::vector<double> mean = LeaveOneOutMeans(rows).mean(R);
    const double fit_error = fit_power_law(t, mean, 1e4, 1e5).exponent_error;
    fit_var += fit_error * fit_error / M;
  }
  // The mean of M jackknife variances, each ~ var chi^2_(R-1)/(R-1) (relative
  // spread sqrt(2/9) = 0.47), has a relative error 0.47/sqrt(400) = 2.4%: 4 of them.
  EXPECT_NEAR(jack_var / var, 1.0, 0.1) << "true " << std::sqrt(var) << ", jackknife " << std::sqrt(jack_var);
  // The least-squares error, which treats the K correlated times as independent,
  // is far too small (measured: about a third of the true error).
  EXPECT_LT(fit_var, 0.25 * var);
}

TEST(Jackknife, DecadeWindowsOfAPowerLaw) {
  // T = t^(-2/3) times a constant per realization: every window's exponent is
  // -2/3 and its jackknife error 0 (a constant factor does not change a slope).
  std::vector<double> t;
  for (int k = 0; k <= 40; ++k) t.push_back(std::pow(10.0, k / 10.0 + 0.5));  // 10^0.5 .. 10^4.5
  std::vector<std::vector<double>> rows;
  for (const double c : {1.0, 1.3, 0.8}) {
    rows.emplace_back();
    for (const double ti : t) rows.back().push_back(c * std::pow(ti, -2.0 / 3.0));
  }
  const std::vector<WindowExponent> w = jackknife_decade_windows(t, rows);
  // One decade: [10, 100] .. [1000, 10^4]; two: [10, 1000], [100, 10^4].
  ASSERT_EQ(w.size(), 5u);
  EXPECT_EQ(w.front().t_min, 10.0);
  EXPECT_EQ(w.back().t_max, 1e4);
  for (const WindowExponent& x : w) {
    EXPECT_NEAR(x.exponent.value, -2.0 / 3.0, 1e-13);
    EXPECT_NEAR(x.exponent.error, 0.0, 1e-13);
  }
}

TEST(Jackknife, PairedExponentsCancelWhatTheStartsShare) {
  // Each start its own exponent (-2/3 + e_i) and amplitude; the gas from it
  // that start's T times t^(-0.01): the difference is -0.01 whichever
  // realization is left out (the log of a mean times t^(-0.01) is a straight
  // line's shift), its error 0 to rounding, while the sticky gas's own
  // exponent carries the starts' spread.
  std::vector<double> t;
  for (int k = 0; k <= 40; ++k) t.push_back(std::pow(10.0, k / 10.0));
  std::vector<std::vector<double>> sticky, gas;
  const double e[] = {0.03, -0.02, 0.01, -0.04};
  const double amplitude[] = {0.21, 0.2, 0.23, 0.19};
  for (std::size_t i = 0; i < 4; ++i) {
    sticky.emplace_back(), gas.emplace_back();
    for (const double ti : t) {
      sticky.back().push_back(amplitude[i] * std::pow(ti, -2.0 / 3.0 + e[i]));
      gas.back().push_back(sticky.back().back() * std::pow(ti, -0.01));
    }
  }
  const PairedExponents p = jackknife_paired_T_exponents(t, gas, sticky, 100, 1e4);
  EXPECT_NEAR(p.difference.value, -0.01, 1e-12);
  EXPECT_NEAR(p.difference.error, 0.0, 1e-12);
  EXPECT_EQ(p.sticky.value, jackknife_T_exponent(t, sticky, 100, 1e4).value);
  EXPECT_GT(p.sticky.error, 0.005);  // the starts' exponents spread by 0.03
  // A realization that stopped early (its row cut at 10^3): its sticky twin is
  // cut at the same sample, and the difference is still the gas's own -0.01.
  gas[1].resize(31);
  const PairedExponents cut = jackknife_paired_T_exponents(t, gas, sticky, 100, 1e4);
  EXPECT_NEAR(cut.difference.value, -0.01, 1e-12);
  EXPECT_NEAR(cut.difference.error, 0.0, 1e-12);
  sticky.pop_back();
  EXPECT_THROW(jackknife_paired_T_exponents(t, gas, sticky, 100, 1e4), InputError);
}

TEST(Jackknife, DistributionErrorsVanishForIdenticalRealizations) {
  // Identical realizations: every leave-one-out mean equals the full one, so the
  // errors are 0 and the values those of analyse_velocity_distribution.
  ZHistogram h;
  h.zmax = 4, h.bins = 40, h.t = {10, 100, 1000};
  std::vector<double> row;
  for (std::size_t k = 0; k < h.t.size(); ++k)
    for (std::size_t b = 0; b < h.bins; ++b) {
      const double z = h.centre(b) * (1 + 0.05 * static_cast<double>(k));
      row.push_back(std::exp(-std::abs(z * z * z) / 2));
    }
  h.density = row;
  const DistributionAnalysis a = analyse_velocity_distribution(h, 10);
  const DistributionErrors e = jackknife_distribution(h, {row, row, row}, 10);
  ASSERT_TRUE(a.collapse_distance.has_value());
  EXPECT_DOUBLE_EQ(e.collapse_distance.value, *a.collapse_distance);
  // The tail exponent minimises a flat residual sum, so rounding of the means
  // (sum / 3 against the row) moves it by ~sqrt(machine epsilon) relative.
  EXPECT_NEAR(e.tail_exponent.value, a.tail.exponent, 1e-7 * a.tail.exponent);
  EXPECT_NEAR(e.collapse_distance.error, 0.0, 1e-15);
  EXPECT_NEAR(e.tail_exponent.error, 0.0, 1e-7 * a.tail.exponent);
  const JackknifeEstimate joint = jackknife_joint_collapse(h, {{row, row}, {row, row}}, 10);
  EXPECT_GT(joint.value, 0.0);
  EXPECT_NEAR(joint.error, 0.0, 1e-15);
}

}  // namespace
}  // namespace shockgas::compare
