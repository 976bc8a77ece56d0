#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

#include "reference_table.hpp"
#include "shockgas/compare/airy.hpp"
#include "shockgas/compare/chernoff.hpp"
#include "shockgas/compare/chernoff_table.hpp"
#include "shockgas/compare/cluster_velocity_law.hpp"
#include "shockgas/compare/eulerian_velocity_law.hpp"
#include "shockgas/compare/gauss_legendre.hpp"
#include "shockgas/compare/goodness_of_fit.hpp"
#include "shockgas/core/error.hpp"
#include "shockgas/core/initial_condition.hpp"
#include "shockgas/core/random.hpp"

namespace shockgas::compare {
namespace {

TEST(ClusterVelocityLaw, ZeroSumExpansionMeetsTheDirectSum) {
  // Below s = 0.3 the library uses the expansion; the direct sum over 1000 zeros
  // (exp(a_1000 s) ~ e^-70) is exact there too. Measured 5e-13 at s = 0.3.
  for (double s : {0.25, 0.29, 0.2999999}) {
    double direct = 0;
    for (int k = 1; k <= 1000; ++k) direct += std::exp(airy_ai_zero(k).a * s);
    EXPECT_NEAR(airy_zero_exponential_sum(s) / direct, 1.0, 1e-12) << s;
  }
  EXPECT_NEAR(airy_zero_exponential_sum(0.3) / airy_zero_exponential_sum(0.2999999), 1.0, 1e-6);
  EXPECT_THROW(airy_zero_exponential_sum(0.0), InputError);
}

TEST(ClusterVelocityLaw, TableOfLnGIsTheDirectEvaluation) {
  // Degree-20 Chebyshev on quarters: to the direct value's rounding (measured 6e-15).
  const ChernoffLogGTable& table = chernoff_log_g_table();
  EXPECT_EQ(table.lo(), -11.0);
  EXPECT_EQ(table.hi(), 12.0);
  for (double x = -11.0; x <= 12.0; x += 0.1371) {
    const double direct = chernoff_log_g(x);
    EXPECT_NEAR(table.log_g(x), direct, 1e-13 * std::max(1.0, std::abs(direct))) << x;
  }
}

// Points taken side by side (8 at a time, and the rest) give each the bits of
// Clenshaw's sum for that point alone, written out here from the coefficients;
// past the table's range, the direct evaluation.
TEST(ClusterVelocityLaw, LnGOfManyPointsIsEachPointsOwnSumToTheBit) {
  const ChernoffLogGTable& table = chernoff_log_g_table();
  const auto& c = table.coefficients();
  auto alone = [&](double x) {
    if (!(x >= table.lo() && x <= table.hi())) return chernoff_log_g(x);
    const int panels = static_cast<int>(c.size() / 21);
    const int p = std::min(panels - 1, static_cast<int>((x - table.lo()) / 0.25));
    const double t = (x - (table.lo() + (p + 0.5) * 0.25)) / 0.125;
    const double* a = c.data() + 21 * p;
    double b1 = 0, b2 = 0;
    for (int k = 20; k >= 1; --k) {
      const double b0 = 2 * t * b1 - b2 + a[k];
      b2 = b1, b1 = b0;
    }
    return t * b1 - b2 + a[0];
  };
  Rng rng(7);
  for (std::size_t n : {1, 7, 8, 9, 16, 21}) {
    std::vector<double> x(n), out(n);
    for (double& xi : x) xi = rng.uniform(-12.0, 13.0);  // some past either end
    x.front() = 12.0;                                    // the last panel's right end
    table.log_g(x, out);
    for (std::size_t i = 0; i < n; ++i) EXPECT_EQ(out[i], alone(x[i])) << "x = " << x[i] << ", n = " << n;
  }
  std::vector<double> two(2), one(1);
  EXPECT_THROW(table.log_g(two, one), InputError);
  EXPECT_THROW(ChernoffLogGTable(0.0, 0.1, {}), InputError);  // no panel: nothing to look up
}

// n(alpha, beta) = 2 (alpha + beta) g(alpha) g(beta) K(alpha + beta) integrated over
// alpha > xi, beta > -xi: with mu = alpha + beta = v^2 and alpha in (xi, xi + mu),
// Gauss-Legendre (24 panels x 12 in v on [0, 3.3], 24 points in alpha): a
// quadrature independent of the library's.
double shocks_holding_a_particle_right_of(double xi) {
  const GaussRule rv = gauss_legendre(12), ra = gauss_legendre(24);
  const ChernoffLogGTable& g = chernoff_log_g_table();
  const double width = 3.3 / 24;
  double sum = 0;
  for (int p = 0; p < 24; ++p)
    for (std::size_t i = 0; i < rv.x.size(); ++i) {
      const double v = width * (p + 0.5 + 0.5 * rv.x[i]), mu = v * v;
      double inner = 0;
      for (std::size_t j = 0; j < ra.x.size(); ++j) {
        const double alpha = xi + 0.5 * mu * (1 + ra.x[j]);
        inner += 0.5 * mu * ra.w[j] * g.g(alpha) * g.g(mu - alpha);
      }
      const double K = airy_zero_exponential_sum(std::cbrt(2.0) * mu);
      sum += 0.5 * width * rv.w[i] * 2 * v * 2 * mu * K * inner;
    }
  return sum;
}

TEST(ClusterVelocityLaw, SwitchingIdentityFixesTheShockIntensity) {
  // The cluster of the particle at s = 0 lies right of xi exactly when q*(xi) < 0,
  // so the shock intensity integrated over the shocks holding s = 0 must give
  // Chernoff's density f(xi) at every xi (cluster_velocity_law.hpp). It does, to
  // rounding: measured 1.4e-14 (and 9e-16 with the quadrature doubled); 1e-12.
  for (double xi : {-1.2, -0.5, 0.0, 0.4, 1.0, 1.7})
    EXPECT_NEAR(shocks_holding_a_particle_right_of(xi) / chernoff_density(xi), 1.0, 1e-12) << xi;
}

TEST(ClusterVelocityLaw, MassIsConservedAndTheLawIsSymmetric) {
  const ClusterVelocityLaw& law = cluster_velocity_law();
  // Trapezoid in u on the line (P is analytic and decays like exp(-2|u|^3/3)):
  // total mass 1 (mass conservation, which the switching identity implies).
  double mass = 0, second = 0;
  for (int j = -500; j <= 500; ++j) {
    const double u = 0.01 * j, p = law.mass_density(u);
    mass += 0.01 * p, second += 0.01 * u * u * p;
  }
  EXPECT_NEAR(mass, 1.0, 1e-11);
  EXPECT_NEAR(law.mass_cdf(0.0), 0.5, 1e-13);
  EXPECT_NEAR(law.mass_cdf(law.mass_quantile(0.9)), 0.9, 1e-13);
  EXPECT_NEAR(law.mass_quantile(0.1), -law.mass_quantile(0.9), 1e-12);
  // Narrower than the Eulerian law (E Z^2 = 0.2635596): E_mass u^2 = 0.1757064.
  EXPECT_NEAR(second, 0.1757064, 1e-7);
  // About two shocks per length a. (The exact hull of 10^6 lattice particles at
  // t = 1000 has 1.97 clusters per a: a lattice cannot hold the smallest shocks.)
  EXPECT_NEAR(law.shock_density(), 2.10848, 1e-5);
}

TEST(ClusterVelocityLaw, AgreesWithAnIndependentScipyImplementation) {
  // tests/compare/data/cluster_mass_reference.csv from scripts/reference/exact_laws.py: SciPy's
  // Airy function and zeros, the zero sum completed by the density of the far zeros
  // (no small-mu expansion), ln g by a spline. Tolerance 1e-9 relative (the spline);
  // measured 4e-11.
  for (const auto& r : testing::read_reference_table("cluster_mass_reference.csv"))
    EXPECT_NEAR(cluster_velocity_law().mass_density(r[0]) / r[1], 1.0, 1e-9) << "u = " << r[0];
}

TEST(ClusterVelocityLaw, TailIsTheEulerianTailOverSqrt2UCubed) {
  // For |u| -> inf the mass integral sits at mu ~ u^-2, where g(mu/2 + u) g(mu/2 - u)
  // ~ 2 f(u) exp(-lambda mu) with lambda = u^2 - 1/(2u) - 2^(-2/3)|a_1| (the slopes of
  // ln g on both sides) and K ~ (2^(1/3) mu)^(-3/2)/(2 sqrt(pi)) - 1/4, so
  //     P_mass(u) = f(u) / (sqrt(2) lambda^(3/2)) (1 - 2 sqrt(2) lambda^(-3/2)
  //                 - (15 |u| / 8) lambda^-2 + ...),
  // the last term from the curvature of ln g(u + mu/2). The deviation of the
  // leading form stays within those two terms (measured: 0.74 to 0.94 of them).
  const ClusterVelocityLaw& law = cluster_velocity_law();
  const double a1 = std::abs(airy_ai_zero(1).a);
  for (double u : {3.0, 3.5, 4.0, 4.5, -4.0}) {
    const double au = std::abs(u), lambda = u * u - 0.5 / au - a1 / std::cbrt(4.0);
    const double leading = chernoff_density(u) / (std::sqrt(2.0) * std::pow(lambda, 1.5));
    const double next = 2 * std::sqrt(2.0) * std::pow(lambda, -1.5) + 15 * au / 8 / (lambda * lambda);
    EXPECT_LE(std::abs(law.mass_density(u) / leading - 1), next) << u;
  }
}

TEST(ClusterVelocityLaw, BinMeansAndUnits) {
  const double D = 1.0 / 3, s = std::cbrt(4 * D);
  EXPECT_NEAR(cluster_velocity_density(0.2, D), cluster_velocity_law().mass_density(0.2 / s) / s, 1e-15);
  EXPECT_NEAR(cluster_velocity_quantile(0.95, D), s * cluster_velocity_law().mass_quantile(0.95), 1e-14);
  std::vector<double> edges;
  for (int j = -30; j <= 30; ++j) edges.push_back(0.1 * j);
  const std::vector<double> bins = cluster_law_on_bins(edges, D);
  const double inside = cluster_velocity_cdf(3.0, D) - cluster_velocity_cdf(-3.0, D);
  EXPECT_NEAR(0.1 * std::accumulate(bins.begin(), bins.end(), 0.0), inside, 1e-13);
  EXPECT_THROW(cluster_velocity_density(0.0, 0.0), InputError);
}

TEST(ClusterVelocityLaw, ExactStickyGasFollowsTheMassWeightedLaw) {
  // r = 0 from white noise: the exact hull of N = 10^6 lattice particles with
  // velocities uniform on [-1, 1] (D = 1/3) at t = 1000 (a = 110 spacings, as in
  // test_eulerian_hopf_lax.cpp), sampled at every 4a-th particle: the velocity of
  // its cluster. Particles 4a apart lie in different clusters (the largest hold
  // ~3a) and the test checks that neighbouring samples are uncorrelated.
  InitialParams p;
  p.N = 1000000;
  p.seed = 1;
  const double t = 1000, D = white_noise_intensity(p);
  const Bodies bodies = make_initial_bodies(p);
  const double U = std::accumulate(bodies.v.begin(), bodies.v.end(), 0.0) / static_cast<double>(p.N);
  const auto clusters = sticky_clusters_ring(bodies, static_cast<double>(p.N), t);
  const auto stride = static_cast<std::size_t>(4 * std::cbrt(4 * D * t * t));
  const std::vector<double> z = cluster_velocity_samples(clusters, p.N, U, t, stride);
  const auto n = static_cast<double>(z.size());
  ASSERT_GT(z.size(), 2200u);
  double lag = 0, var = 0;
  for (std::size_t i = 0; i + 1 < z.size(); ++i) lag += z[i] * z[i + 1];
  for (const double x : z) var += x * x;
  EXPECT_LT(std::abs(lag / var), 4 / std::sqrt(n));
  // Pearson's chi-square, 20 equiprobable bins, nothing fitted: reject below
  // p = 1e-3. Seed 1: X^2 = 18.4 (19 dof), p = 0.49.
  const ChiSquareTest fit = chi_square_test(
      z, [&](double q) { return cluster_velocity_quantile(q, D); }, 20);
  RecordProperty("chi_square", std::to_string(fit.statistic));
  RecordProperty("p_value", std::to_string(fit.p_value));
  EXPECT_GT(fit.p_value, 1e-3) << "X^2 = " << fit.statistic;
  // The same samples reject the Eulerian law (measured X^2 = 158, p ~ 1e-24).
  const ChiSquareTest eulerian = chi_square_test(
      z, [&](double q) { return eulerian_velocity_quantile(q, D); }, 20);
  EXPECT_LT(eulerian.p_value, 1e-10);
}

}  // namespace
}  // namespace shockgas::compare
