#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "shockgas/compare/cluster_velocity_law.hpp"
#include "shockgas/compare/velocity_tail.hpp"
#include "shockgas/core/error.hpp"
#include "shockgas/core/random.hpp"

namespace shockgas::compare {
namespace {

constexpr double kD = 1.0 / 3.0;  // uniform velocities on [-1, 1] at unit spacing

TEST(VelocityTail, FoldsAndCountsClusters) {
  TailHistogram h(0.5, 2.0);
  ASSERT_EQ(h.bins(), 4u);
  h.add(0.2, 3);   // bin 0
  h.add(-0.7, 2);  // bin 1 (folded)
  h.add(5.0, 1);   // beyond z_max: in the totals only
  const std::vector<double> z{0.6, 0.9, -1.2, 0.55}, m{1, 1, 1, 1};
  h.add_members(z, m);  // bins 1, 1, 2, 1: one cluster in bins 1 and 2
  EXPECT_EQ(h.mass(), (std::vector<double>{3, 5, 1, 0}));
  EXPECT_EQ(h.clusters(), (std::vector<double>{1, 2, 1, 0}));
  EXPECT_EQ(h.total_mass(), 10.0);
  EXPECT_EQ(h.total_clusters(), 4.0);
  EXPECT_THROW(TailHistogram(0.0, 1.0), InputError);
}

// R realizations of n clusters of mass 1 whose |z| is drawn from a folded law
// given by its bin probabilities (so the histogram is multinomial, as for
// independent clusters).
std::vector<TailHistogram> draw(const std::vector<double>& probability, double width, std::size_t R,
                                std::size_t n, std::uint64_t seed) {
  std::vector<double> cumulative(probability.size());
  double c = 0;
  for (std::size_t b = 0; b < probability.size(); ++b) cumulative[b] = c += probability[b];
  std::vector<TailHistogram> h;
  for (std::size_t r = 0; r < R; ++r) {
    Rng rng(realization_seed(seed, r));
    TailHistogram x(width, width * static_cast<double>(probability.size()));
    for (std::size_t i = 0; i < n; ++i) {
      const double u = rng.uniform() * c;
      const auto b = static_cast<std::size_t>(std::upper_bound(cumulative.begin(), cumulative.end(), u) -
                                              cumulative.begin());
      x.add((static_cast<double>(std::min(b, probability.size() - 1)) + rng.uniform()) * width, 1.0);
    }
    h.push_back(std::move(x));
  }
  return h;
}

std::vector<double> exact_probabilities(double width, std::size_t bins) {
  std::vector<double> p(bins);
  for (std::size_t b = 0; b < bins; ++b)
    p[b] = 2 * (cluster_velocity_cdf((b + 1) * width, kD) - cluster_velocity_cdf(b * width, kD));
  return p;
}

TEST(VelocityTail, SamplesOfTheExactLawRecoverItsLocalExponent) {
  // 20 realizations of 2 10^5 clusters: the tail reaches |z| = 2 at 25 clusters
  // a bin (measured), where the local exponent's error is about 0.4.
  const double w = 0.05;
  const TailParams params;  // D = 1/3, 25 clusters, 5-bin slopes, from |z| = 0.5
  const auto h = draw(exact_probabilities(w, 120), w, 20, 200000, 99);
  const TailAnalysis a = analyse_tail(h, params);
  EXPECT_GE(a.z_reach, 1.95);
  // Phi against the exact bin means: Pearson's chi-square with the jackknife
  // errors, rejected below p = 1e-3.
  EXPECT_GT(a.p_value, 1e-3) << "X^2 = " << a.chi_square << " on " << a.dof;
  std::size_t checked = 0, within = 0;
  for (const TailPoint& q : a.points) {
    if (q.z < 1.0 || !std::isfinite(q.local_exponent.error)) continue;
    ++checked;
    // The same estimator on the exact bins is the law's own exponent up to the
    // bin average (measured: 0.001 inside, 0.012 at the cut, where the 5-bin
    // window is one-sided).
    EXPECT_NEAR(q.exact_local_bins, q.exact_local, 0.02) << q.z;
    const double pull = (q.local_exponent.value - q.exact_local_bins) / q.local_exponent.error;
    within += std::abs(pull) < 2;
    EXPECT_LT(std::abs(pull), 4.5) << "z = " << q.z << ": " << q.local_exponent.value << " +- "
                                   << q.local_exponent.error << " against " << q.exact_local_bins;
  }
  ASSERT_GT(checked, 15u);
  // About 95% of Gaussian pulls lie within 2; neighbouring slopes share bins, so
  // allow 80%.
  EXPECT_GT(within, 0.8 * checked);
  const TailWindowFit fit = fit_tail_window(h, 1.0, 2.0, params);
  EXPECT_LT(std::abs(fit.exponent.value - fit.exact_exponent), 4 * fit.exponent.error)
      << fit.exponent.value << " +- " << fit.exponent.error << " against " << fit.exact_exponent;
  EXPECT_LT(std::abs(fit.slope.value - fit.exact_slope), 4 * fit.slope.error);
  EXPECT_GT(fit.exact_slope, 1.8);  // the law's own slope over [1, 2]: about 1.9, not 3
  EXPECT_LT(fit.exact_slope, 2.2);
}

TEST(VelocityTail, AGaussianTailOfTheSameWidthIsRejected) {
  // The power of the comparison: a Gaussian with the law's variance (exponent 2
  // at every z) drawn the same way fails the chi-square against the exact law.
  const double w = 0.05, sigma = std::sqrt(0.2129);  // mass-weighted <z^2>, D = 1/3
  std::vector<double> p(120);
  for (std::size_t b = 0; b < p.size(); ++b)
    p[b] = std::erf((b + 1) * w / (sigma * std::sqrt(2.0))) - std::erf(b * w / (sigma * std::sqrt(2.0)));
  const TailAnalysis a = analyse_tail(draw(p, w, 20, 200000, 5), TailParams{});
  EXPECT_LT(a.p_value, 1e-10) << "X^2 = " << a.chi_square << " on " << a.dof;
}

TEST(VelocityTail, ExactLocalExponentAsTabulated) {
  // docs/paper.md's table of the mass-weighted law (D = 1/3), two decimals.
  EXPECT_NEAR(exact_tail_local_exponent(1.0, kD), 1.85, 0.006);
  EXPECT_NEAR(exact_tail_local_exponent(2.0, kD), 2.02, 0.006);
  EXPECT_NEAR(exact_tail_local_exponent(3.5, kD), 2.37, 0.006);
}

}  // namespace
}  // namespace shockgas::compare
