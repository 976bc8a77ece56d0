#include "shockgas/compare/cluster_velocity_law.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

#include "shockgas/compare/airy.hpp"
#include "shockgas/compare/chernoff_table.hpp"
#include "shockgas/compare/eulerian_velocity_law.hpp"
#include "shockgas/compare/gauss_legendre.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::compare {

namespace {

const double kCbrt2 = std::cbrt(2.0);

// Small-s expansion of sum_k exp(a_k s) = Hankel transform of Ai'/Ai term by term:
// Ai'/Ai ~ -sqrt(w) sum_k c_k zeta^-k (c = 1, 1/6, -5/72, 5/72, -1105/10368, ...,
// the ratio of the expansions of Ai' and Ai, DLMF 9.7.5-6), and
// (1/2 pi i) int_H e^(s w) w^nu dw = s^(-nu-1) / Gamma(-nu), so the term k is
// -c_k (3/2)^k s^((3k-3)/2) / Gamma((3k-1)/2). Against the direct sum: 5e-13 at s = 0.3.
constexpr std::array<double, 9> kSmallS = {
    0.28209479177387814,     // 1 / (2 sqrt(pi))            s^(-3/2)
    -0.25,                   //                              s^0
    0.11753949657244922,     // 5 / (24 sqrt(pi))           s^(3/2)
    -0.0390625,              // -5/128                       s^3
    0.010308027278774317,    // 221 / (12096 sqrt(pi))      s^(9/2)
    -0.0022989908854166665,  // -113/49152                   s^6
    0.0004502538574209636,   // 16565 / (20756736 sqrt(pi)) s^(15/2)
    -7.942240074198082e-05,  // -3935/49545216               s^9
    1.2843485452915384e-05,  //                              s^(21/2)
};
constexpr double kDirectFrom = 0.3;

// mu = v^2, v in [0, 3.25] on 13 panels of 16 points: mu^power K dmu = 2 v^(2 power + 1) K dv.
constexpr double kVMax = 3.25;  // mu <= 10.6: the integrand is below exp(-190) of its peak beyond
constexpr int kVPanels = 13;
// The CDF table: panels of width 0.05 on [-5, 5] (P_mass(5) ~ 1e-40).
constexpr double kUMax = 5.0, kUPanel = 0.05;

}  // namespace

std::vector<double> compute_airy_zeros() {
  std::vector<double> a;
  for (int k = 1; k <= 1000; ++k) a.push_back(airy_ai_zero(k).a);
  return a;
}

double airy_zero_exponential_sum(double s) {
  require_above("airy.exponential_sum_s", s, 0.0);
  if (s < kDirectFrom) {
    double sum = 0, power = std::pow(s, -1.5);
    const double step = std::pow(s, 1.5);
    for (const double c : kSmallS) sum += c * power, power *= step;
    return sum;
  }
  double sum = 0;
  for (const double a : airy_zeros()) {
    const double term = std::exp(a * s);
    sum += term;
    if (term < 1e-17 * sum) return sum;
  }
  throw RunError("airy_zero_exponential_sum: 1000 zeros did not suffice");
}

ClusterVelocityLaw::ClusterVelocityLaw() {
  const GaussRule rule = gauss_legendre(16);
  const double width = kVMax / kVPanels;
  for (int p = 0; p < kVPanels; ++p)
    for (std::size_t i = 0; i < rule.x.size(); ++i) {
      const double v = width * (p + 0.5 + 0.5 * rule.x[i]);
      n_.mu.push_back(v * v);
      n_.weight.push_back(0.5 * width * rule.w[i] * 2 * v * airy_zero_exponential_sum(kCbrt2 * v * v));
    }
  const int panels = static_cast<int>(std::round(2 * kUMax / kUPanel));
  n_.cumulative.assign(1, 0.0);
  const GaussRule r = gauss_legendre(8);
  double number = 0;
  for (int p = 0; p < panels; ++p) {
    const double a = -kUMax + p * kUPanel;
    n_.cumulative.push_back(n_.cumulative.back() + mass_integral(a, a + kUPanel));
    for (std::size_t i = 0; i < r.x.size(); ++i)
      number += 0.5 * kUPanel * r.w[i] * 2 * moment_sum(a + kUPanel * 0.5 * (1 + r.x[i]), 1);
  }
  n_.shocks = number;
}

ClusterVelocityLaw::ClusterVelocityLaw(Nodes nodes) : n_(std::move(nodes)) {
  require(n_.mu.size() == n_.weight.size() && !n_.mu.empty() &&
              n_.cumulative.size() == static_cast<std::size_t>(std::round(2 * kUMax / kUPanel)) + 1,
          "cluster_law.nodes", n_.mu.size(), "a law's nodes and its CDF table on [-5, 5]");
}

double ClusterVelocityLaw::moment_sum(double u, int power) const {  // power 1 or 2
  const ChernoffLogGTable& g = chernoff_log_g_table();
  double sum = 0;
  for (std::size_t j = 0; j < n_.mu.size(); ++j) {
    const double m = n_.mu[j];
    sum += n_.weight[j] * (power == 2 ? m * m : m) * std::exp(g.log_g(0.5 * m + u) + g.log_g(0.5 * m - u));
  }
  return sum;
}

double ClusterVelocityLaw::mass_density(double u) const { return 2 * moment_sum(u, 2); }

double ClusterVelocityLaw::number_density(double u) const { return 2 * moment_sum(u, 1) / n_.shocks; }

double ClusterVelocityLaw::mass_integral(double a, double b) const {
  static const GaussRule rule = gauss_legendre(8);
  const int panels = std::max(1, static_cast<int>(std::ceil(std::abs(b - a) / kUPanel)));
  const double width = (b - a) / panels;
  double sum = 0;
  for (int p = 0; p < panels; ++p)
    for (std::size_t i = 0; i < rule.x.size(); ++i)
      sum += rule.w[i] * mass_density(a + width * (p + 0.5 + 0.5 * rule.x[i]));
  return 0.5 * width * sum;
}

double ClusterVelocityLaw::mass_cdf(double u) const {
  if (u <= -kUMax) return 0.0;
  if (u >= kUMax) return 1.0;
  const auto p = static_cast<std::size_t>((u + kUMax) / kUPanel);
  const double left = -kUMax + static_cast<double>(p) * kUPanel;
  return n_.cumulative[p] + mass_integral(left, u);
}

double ClusterVelocityLaw::mass_quantile(double p) const {
  require(p > 0 && p < 1, "cluster_law.p", p, "0 < p < 1");
  // Bracket in the table, then Newton with the density (the CDF is smooth and increasing).
  const auto it = std::upper_bound(n_.cumulative.begin(), n_.cumulative.end(), p);
  const auto k = static_cast<std::size_t>(std::max<std::ptrdiff_t>(1, it - n_.cumulative.begin())) - 1;
  double u = -kUMax + static_cast<double>(k) * kUPanel, c = n_.cumulative[k];
  for (int iteration = 0; iteration < 50; ++iteration) {
    const double step = (p - c) / mass_density(u);
    if (!(std::abs(step) > 1e-15 * std::max(1.0, std::abs(u)))) break;
    c += mass_integral(u, u + step);
    u += step;
  }
  return u;
}

// int u^2 P_mass(u) du on [-5, 5] (P_mass(5) ~ 1e-40), 8-point Gauss-Legendre on
// panels of 0.05: the integrand is smooth, the rule exact to rounding long before.
double compute_cluster_law_second_moment(const ClusterVelocityLaw& law) {
  const GaussRule rule = gauss_legendre(8);
  double sum = 0;
  for (int p = 0; p < static_cast<int>(2 * kUMax / kUPanel); ++p)
    for (std::size_t i = 0; i < rule.x.size(); ++i) {
      const double u = -kUMax + kUPanel * (p + 0.5 + 0.5 * rule.x[i]);
      sum += 0.5 * kUPanel * rule.w[i] * u * u * law.mass_density(u);
    }
  return sum;
}

double cluster_velocity_density(double z, double D) {
  const double s = eulerian_velocity_scale(D);
  return cluster_velocity_law().mass_density(z / s) / s;
}

double cluster_velocity_cdf(double z, double D) {
  return cluster_velocity_law().mass_cdf(z / eulerian_velocity_scale(D));
}

double cluster_velocity_quantile(double p, double D) {
  return eulerian_velocity_scale(D) * cluster_velocity_law().mass_quantile(p);
}

std::vector<double> cluster_law_on_bins(std::span<const double> z_edges, double D) {
  const ClusterVelocityLaw& law = cluster_velocity_law();
  return scaled_law_on_bins(z_edges, eulerian_velocity_scale(D),
                            [&](double a, double b) { return law.mass_integral(a, b); });
}

std::vector<double> cluster_velocity_samples(const std::vector<StickyCluster>& clusters, std::size_t bodies,
                                             double mean_velocity, double t, std::size_t stride) {
  require_above("compare.t", t, 0.0);
  require(stride >= 1, "compare.stride", stride, ">= 1");
  std::vector<double> velocity(bodies, std::numeric_limits<double>::quiet_NaN());
  for (const StickyCluster& c : clusters)
    for (std::size_t k = c.first; k < c.first + c.count; ++k) velocity[k % bodies] = c.v;
  const double scale = std::cbrt(t);
  std::vector<double> z;
  for (std::size_t j = 0; j < bodies; j += stride) {
    require(!std::isnan(velocity[j]), "compare.clusters", j, "clusters that hold every body");
    z.push_back((velocity[j] - mean_velocity) * scale);
  }
  return z;
}

}  // namespace shockgas::compare
