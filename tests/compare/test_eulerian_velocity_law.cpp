#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <vector>

#include "shockgas/compare/chernoff.hpp"
#include "shockgas/compare/eulerian_velocity_law.hpp"
#include "shockgas/compare/goodness_of_fit.hpp"
#include "shockgas/continuum/hopf_lax.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::compare {
namespace {

TEST(EulerianVelocityLaw, IntensityAndScale) {
  InitialParams p;
  p.N = 1000;
  EXPECT_NEAR(white_noise_intensity(p), 1.0 / 3, 1e-16);  // uniform on [-1, 1], unit spacing
  p.velocities = Velocities::gaussian;
  p.amplitude = 2;
  p.L = 500;
  EXPECT_NEAR(white_noise_intensity(p), 4 * 0.5, 1e-15);  // sigma^2 l
  EXPECT_NEAR(eulerian_velocity_scale(1.0 / 3), std::cbrt(4.0 / 3), 1e-15);
  p.velocities = Velocities::expression;
  EXPECT_THROW(white_noise_intensity(p), InputError);
  p.velocities = Velocities::uniform;
  p.positions = Positions::random;
  EXPECT_THROW(white_noise_intensity(p), InputError);
}

TEST(EulerianVelocityLaw, IsTheScaledChernoffLaw) {
  const double D = 1.0 / 3, s = std::cbrt(4 * D);
  EXPECT_NEAR(eulerian_velocity_density(0.3, D), chernoff_density(0.3 / s) / s, 1e-15);
  EXPECT_NEAR(eulerian_velocity_quantile(0.95, D), s * chernoff_quantile(0.95), 1e-15);
  EXPECT_NEAR(eulerian_velocity_cdf(eulerian_velocity_quantile(0.7, D), D), 0.7, 1e-13);
  // Bin means over [-3, 3] sum to the mass inside, 1 - 2 P(Z > 3/s) = 1 - 7e-10
  // (both by Gauss-Legendre panels: to rounding).
  std::vector<double> edges;
  for (int j = -30; j <= 30; ++j) edges.push_back(0.1 * j);
  const std::vector<double> bins = eulerian_law_on_bins(edges, D);
  EXPECT_NEAR(0.1 * std::accumulate(bins.begin(), bins.end(), 0.0), 1 - 2 * chernoff_survival(3 / s), 1e-14);
  const DensityCurve curve = eulerian_law_curve(D, 3.0, 61);
  EXPECT_NEAR(curve.z[30], 0.0, 1e-15);
  EXPECT_NEAR(curve.density[30], chernoff_density(0) / s, 1e-15);
}

// A sawtooth of slope 1/t with two shocks, one of them inside a sampled cell,
// given as exact cell averages: the samples are the centre values.
TEST(EulerianVelocityLaw, SamplesAreCentreValuesOfTheRamps) {
  continuum::ContinuumResult f;
  f.t = 4, f.length = 10, f.has_shocks = true;
  const std::size_t cells = 20;
  const double dx = 0.5;
  // v = (x - 1)/t on [0, 2.3), (x - 6)/t on [2.3, 7.05), (x - 11)/t on [7.05, 10): periodic.
  auto v = [&](double x) { return (x - (x < 2.3 ? 1.0 : x < 7.05 ? 6.0 : 11.0)) / f.t; };
  f.shocks = {{2.3, 5.0, -5.0 / f.t, 0.0}, {7.05, 5.0, -5.0 / f.t, 0.0}};
  for (std::size_t i = 0; i < cells; ++i) {  // exact averages (piecewise linear: midpoint rule per piece)
    const double s = i * dx, e = s + dx;
    double sum = 0, a = s;
    for (double cut : {2.3, 7.05, e}) {
      if (cut <= a || cut > e) continue;
      sum += (cut - a) * v(0.5 * (a + cut));
      a = cut;
    }
    f.v.push_back(sum / dx);
  }
  const double mean = std::accumulate(f.v.begin(), f.v.end(), 0.0) / cells;
  const std::vector<double> z = eulerian_scaled_samples(f, 2);  // cells 0, 2, 4, ... (cell 4 holds 2.3)
  ASSERT_EQ(z.size(), 10u);
  for (std::size_t k = 0; k < z.size(); ++k) {
    const double centre = (2 * k + 0.5) * dx;
    EXPECT_NEAR(z[k], (v(centre) - mean) * std::cbrt(f.t), 1e-14) << centre;
  }
  f.has_shocks = false;
  EXPECT_THROW(eulerian_scaled_samples(f, 2), InputError);
}

}  // namespace
}  // namespace shockgas::compare
