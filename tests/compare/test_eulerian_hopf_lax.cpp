// The Eulerian velocity of the exact (hopf_lax) field from white noise against
// its exact law (eulerian_velocity_law.hpp): z = (v - U) t^(1/3) ~ (4D)^(1/3) Z.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "shockgas/compare/eulerian_velocity_law.hpp"
#include "shockgas/compare/goodness_of_fit.hpp"
#include "shockgas/continuum/hopf_lax.hpp"
#include "shockgas/core/initial_condition.hpp"

namespace shockgas::compare {
namespace {

// One realization of the white-noise scene at N = 10^6 (uniform velocities on
// [-1, 1], unit spacing: D = 1/3), solved exactly at t = 1000, sampled at points
// four shock spacings apart.
//  * t = 1000: the Lagrangian scale a = (4 D t^2)^(1/3) = 110 spacings, so the
//    random walk is Brownian on that scale (lattice corrections ~ 1/a = 1%,
//    below what 4300 samples resolve, ~5% in the scale); a / L = 1e-4 (ring).
//  * Resolution: v = (x - q*)/t with q* on the lattice, so at one x the values
//    are 1/t apart, t^(-2/3) = 0.01 in z, 1/56 of its standard deviation. The
//    cell centres sit at x = (i + 1/2) dx with dx = L / cells = 1/phi (golden
//    ratio): their offsets from the lattice are equidistributed, so these
//    discrete values do not alias the bins (with dx = 1/4 and a stride that is
//    a multiple of 4, every sample has the same offset, and at t = 100 the
//    test rejects the law with p < 1e-20 for that reason alone).
//  * Independence: points 4 shock spacings apart (4 x 58 = 230 spacings) sit on
//    different ramps with different Lagrangian neighbourhoods; the test checks
//    that neighbouring samples are uncorrelated.
struct WhiteNoiseSample {
  std::vector<double> z;
  double D = 0;
  std::size_t shocks = 0;
};

WhiteNoiseSample white_noise_sample() {
  InitialParams p;
  p.N = 1000000;
  p.velocities = Velocities::uniform;
  p.seed = 1;
  const double t = 1000;
  const auto cells = static_cast<std::size_t>(static_cast<double>(p.N) * std::numbers::phi);
  const continuum::ContinuumResult field = continuum::solve_hopf_lax(make_initial_field(p), cells, t);
  const double shock_spacing = static_cast<double>(p.N) / static_cast<double>(field.shocks.size());
  const double dx = static_cast<double>(p.N) / static_cast<double>(cells);
  const auto stride = static_cast<std::size_t>(4 * shock_spacing / dx);
  return {eulerian_scaled_samples(field, stride), white_noise_intensity(p), field.shocks.size()};
}

double lag_one_correlation(const std::vector<double>& z) {
  double c = 0, v = 0;
  for (std::size_t i = 0; i + 1 < z.size(); ++i) c += z[i] * z[i + 1];
  for (const double x : z) v += x * x;
  return c / v;
}

TEST(EulerianHopfLax, WhiteNoiseFollowsTheChernoffLaw) {
  const WhiteNoiseSample s = white_noise_sample();
  const auto n = static_cast<double>(s.z.size());
  ASSERT_GT(s.z.size(), 4000u);  // 10^6 / (4 x 58)
  // Neighbouring samples uncorrelated: |rho_1| < 4 / sqrt(n) (4 standard errors).
  EXPECT_LT(std::abs(lag_one_correlation(s.z)), 4 / std::sqrt(n));
  // Pearson's chi-square on 20 equiprobable bins (~215 samples each), no
  // parameter fitted: reject below p = 1e-3. Seed 1 gives X^2 = 19.6 (19 dof), p = 0.42.
  auto law = [&](double p) { return eulerian_velocity_quantile(p, s.D); };
  const ChiSquareTest fit = chi_square_test(s.z, law, 20);
  RecordProperty("samples", static_cast<int>(s.z.size()));
  RecordProperty("chi_square", std::to_string(fit.statistic));
  RecordProperty("p_value", std::to_string(fit.p_value));
  EXPECT_GT(fit.p_value, 1e-3) << "X^2 = " << fit.statistic << " with " << fit.dof << " dof";
  // The test has power: the same samples reject a scale 10% too large
  // (D x 1.1^3), measured X^2 = 81, p ~ 1e-9.
  auto wrong = [&](double p) { return eulerian_velocity_quantile(p, s.D * 1.331); };
  EXPECT_LT(chi_square_test(s.z, wrong, 20).p_value, 1e-6);
}

}  // namespace
}  // namespace shockgas::compare
