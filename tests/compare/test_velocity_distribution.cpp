#include <gtest/gtest.h>

#include <cmath>

#include "shockgas/compare/velocity_distribution.hpp"
#include "shockgas/core/error.hpp"
#include "shockgas/core/random.hpp"

namespace shockgas::compare {
namespace {

double phi_exact(double z) { return 0.7 * std::exp(-1.3 * std::abs(z * z * z)); }

TEST(VelocityDistribution, TailExponentOfAnExactDensityIsThree) {
  std::vector<double> z, phi;
  for (int i = -300; i <= 300; ++i) {
    z.push_back(0.01 * i);
    phi.push_back(phi_exact(z.back()));
  }
  const TailFit f = fit_tail_exponent(z, phi, 1.0);
  // An exact fit: RSS(a) ~ k (a - 3)^2 with RSS(3) at rounding (~1e-30), so the
  // golden section resolves a to ~ 1e-13; 1e-8 leaves ample room.
  EXPECT_NEAR(f.exponent, 3.0, 1e-8);
  EXPECT_NEAR(f.c, 1.3, 1e-7);
  EXPECT_NEAR(f.phi0, 0.7, 1e-7);
  EXPECT_EQ(f.points, 402u);  // |z| in [1, 3] on both sides
}

TEST(VelocityDistribution, TailExponentFromBinnedDensity) {
  // Bin averages of the exact density (Simpson, 64 sub-intervals per bin) on
  // bins of width 0.05: the bin centre value differs from the average by
  // ~ w^2 phi'' / 24 ~ 1e-4 phi (relative, for |z| <= 3), which moves a by a few
  // 1e-3 (measured -3.6e-3).
  ScaledDistribution d;
  d.t = 1;
  const double w = 0.05;
  for (int j = -80; j <= 80; ++j) d.z_edges.push_back(j * w);
  for (std::size_t j = 0; j + 1 < d.z_edges.size(); ++j) {
    const double a = d.z_edges[j], h = w / 64;
    double s = phi_exact(a) + phi_exact(a + w);
    for (int k = 1; k < 64; ++k) s += (k % 2 ? 4 : 2) * phi_exact(a + k * h);
    d.density.push_back(s * h / 3 / w);
  }
  const TailFit f = fit_tail_exponent(d, 1.0);
  EXPECT_NEAR(f.exponent, 3.0, 1e-2);
}

TEST(VelocityDistribution, ScaledHistogramsOfAScalingFormCollapse) {
  // Samples v = z / t^(1/3) with z ~ N(0, 1) at three times collapse onto one
  // density; without the scaling (t = 1 for all) they do not.
  Rng rng(31);
  std::vector<ScaledDistribution> scaled, unscaled;
  for (double t : {1e3, 1e4, 1e5}) {
    std::vector<double> v;
    for (int i = 0; i < 20000; ++i) v.push_back(rng.normal() / std::cbrt(t));
    scaled.push_back(scaled_histogram(v, {}, t, 4.0, 40));
    std::vector<double> v_as_z(v);
    for (double& x : v_as_z) x *= std::cbrt(1e3);
    unscaled.push_back(scaled_histogram(v_as_z, {}, 1.0, 4.0, 40));
  }
  const double d_scaled = collapse_distance(scaled);
  const double d_unscaled = collapse_distance(unscaled);
  // Sampling noise of a 40-bin histogram of 20000 samples: sum over bins of
  // sqrt(2 n_j) / N ~ sqrt(2 * 40 / 20000) * (a shape factor < 1) ~ 0.05.
  EXPECT_LT(d_scaled, 0.06);  // measured 0.043
  // Widths differing by 10^(1/3) and 10^(2/3): L1 distances of order 1.
  EXPECT_GT(d_unscaled, 0.5);  // measured 0.87
}

TEST(VelocityDistribution, FlatTailIsFlaggedAtTheBound) {
  // A density that does not decay: RSS is smallest for the smallest a tried.
  std::vector<double> z, phi;
  for (int i = 10; i <= 30; ++i) {
    z.push_back(0.1 * i);
    phi.push_back(0.2 + 0.01 * (i % 3));
  }
  const TailFit f = fit_tail_exponent(z, phi, 1.0);
  EXPECT_TRUE(f.at_bound);
  EXPECT_TRUE(std::isnan(f.exponent_error));
  // The exact density is not at a bound.
  std::vector<double> phi3;
  for (double zi : z) phi3.push_back(phi_exact(zi));
  EXPECT_FALSE(fit_tail_exponent(z, phi3, 1.0).at_bound);
}

TEST(VelocityDistribution, MeanOfDistributionsAveragesBins) {
  ScaledDistribution a{1.0, {-1, 0, 1}, {0.2, 0.8}}, b{2.0, {-1, 0, 1}, {0.6, 0.4}};
  const ScaledDistribution m = mean_distribution({a, b});
  EXPECT_DOUBLE_EQ(m.density[0], 0.4);
  EXPECT_DOUBLE_EQ(m.density[1], 0.6);
  EXPECT_EQ(m.t, 2.0);
  ScaledDistribution c{3.0, {-2, 0, 2}, {0.1, 0.1}};
  EXPECT_THROW(mean_distribution({a, c}), InputError);
}

TEST(VelocityDistribution, NormalisationAndWeights) {
  // Two samples of weights 1 and 3 at t = 8 (t^(1/3) = 2): z = 0.5 and -1.5.
  const std::vector<double> v{0.25, -0.75}, w{1.0, 3.0};
  const ScaledDistribution d = scaled_histogram(v, w, 8.0, 2.0, 4);  // bins of width 1
  EXPECT_DOUBLE_EQ(d.density[0], 0.75);                              // [-2, -1)
  EXPECT_DOUBLE_EQ(d.density[2], 0.25);                              // [0, 1)
  const std::vector<double> edges{-1, 0, 2}, counts{1, 3};
  const ScaledDistribution r = rescale_v_histogram(edges, counts, 8.0);
  EXPECT_DOUBLE_EQ(r.z_edges[2], 4.0);
  EXPECT_DOUBLE_EQ(r.density[1], 0.75 / 4.0);
  EXPECT_THROW(scaled_histogram(v, w, 0.0, 2.0, 4), InputError);
  EXPECT_THROW(collapse_distance({d}), InputError);
}

}  // namespace
}  // namespace shockgas::compare
