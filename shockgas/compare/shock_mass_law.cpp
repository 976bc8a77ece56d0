#include "shockgas/compare/shock_mass_law.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "shockgas/compare/chernoff_table.hpp"
#include "shockgas/compare/cluster_velocity_law.hpp"
#include "shockgas/compare/gauss_legendre.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::compare {

namespace {

const double kCbrt2 = std::cbrt(2.0);
// (g * g)(mu): the integrand is even in u, and beyond u = 6 it is below
// g(mu/2 + u) sup g < g(6) sup g ~ e^-140 (g(x) ~ 4x exp(-2x^3/3)), while
// (g * g)(mu) itself is about exp(-mu^3/6) (its value at u = 0): negligible
// for the mu <= kMuMax where the law is evaluated. Panels of 0.2 (8-point
// Gauss-Legendre): halving them moves N(mu) by less than 1e-14 of itself at
// mu = 0.001 ... 8 (measured), its rounding; the integral in v below is the
// quadrature that limits the law (about 5e-8, from its panels' convergence).
constexpr double kUMax = 6.0, kUPanel = 0.2;
// Beyond mu = 12, N(mu) < exp(-12^3 / 6) = e^-288 of its scale: taken as 0.
constexpr double kMuMax = 12.0;
// In v = sqrt(mu) the bins' integrand 2 v N(v^2) is smooth: panels of at most 0.05.
constexpr double kVPanel = 0.05;

const GaussRule& rule8() {
  static const GaussRule rule = gauss_legendre(8);
  return rule;
}

double self_convolution(double mu) {
  const ChernoffLogGTable& g = chernoff_log_g_table();
  const GaussRule& r = rule8();
  const int panels = static_cast<int>(std::ceil(kUMax / kUPanel));
  const std::size_t nodes = r.x.size();
  std::vector<double> at(2 * nodes), log_g(2 * nodes);  // g's arguments mu/2 + u, mu/2 - u of a panel
  double sum = 0;
  for (int p = 0; p < panels; ++p) {
    for (std::size_t i = 0; i < nodes; ++i) {
      const double u = kUPanel * (p + 0.5 + 0.5 * r.x[i]);
      at[2 * i] = 0.5 * mu + u, at[2 * i + 1] = 0.5 * mu - u;
    }
    g.log_g(at, log_g);
    for (std::size_t i = 0; i < nodes; ++i)
      sum += 0.5 * kUPanel * r.w[i] * std::exp(log_g[2 * i] + log_g[2 * i + 1]);
  }
  return 2 * sum;
}

}  // namespace

double shock_mass_density(double mu) {
  require_above("compare.shock_mass", mu, 0.0);
  return 2 * mu * airy_zero_exponential_sum(kCbrt2 * mu) * self_convolution(mu);
}

double shock_mass_integral(double mu1, double mu2) {
  require(mu1 >= 0 && mu2 >= mu1 && std::isfinite(mu2), "compare.shock_mass_range", mu2,
          "finite, >= the lower end (" + std::to_string(mu1) + ") >= 0");
  const double v1 = std::sqrt(std::min(mu1, kMuMax)), v2 = std::sqrt(std::min(mu2, kMuMax));
  if (v2 <= v1) return 0.0;
  const int panels = std::max(1, static_cast<int>(std::ceil((v2 - v1) / kVPanel)));
  const double width = (v2 - v1) / panels;
  const GaussRule& r = rule8();
  double sum = 0;
  for (int p = 0; p < panels; ++p)
    for (std::size_t i = 0; i < r.x.size(); ++i) {
      const double v = v1 + width * (p + 0.5 + 0.5 * r.x[i]);
      sum += 0.5 * width * r.w[i] * 2 * v * shock_mass_density(v * v);
    }
  return sum;
}

std::vector<double> expected_shocks_in_mass_bins(std::span<const double> mass_edges, double D, double L,
                                                 double rho, double t) {
  require(mass_edges.size() >= 2 && mass_edges.front() >= 0, "compare.mass_edges", mass_edges.size(),
          ">= 2 edges from >= 0");
  for (const auto& [name, value] :
       {std::pair{"compare.D", D}, {"compare.length", L}, {"compare.density", rho}, {"compare.t", t}})
    require_above(name, value, 0.0);
  const double a = std::cbrt(4 * D * t * t), mass_unit = rho * a;
  std::vector<double> count;
  for (std::size_t j = 0; j + 1 < mass_edges.size(); ++j) {
    require(mass_edges[j + 1] > mass_edges[j], "compare.mass_edges", mass_edges[j + 1], "increasing edges");
    count.push_back(L / a * shock_mass_integral(mass_edges[j] / mass_unit, mass_edges[j + 1] / mass_unit));
  }
  return count;
}

std::vector<double> expected_shocks_above(double mass, double D, double L, double rho,
                                          std::span<const double> t) {
  require(mass >= 0, "compare.mass", mass, ">= 0");
  for (const auto& [name, value] :
       {std::pair{"compare.D", D}, {"compare.length", L}, {"compare.density", rho}})
    require_above(name, value, 0.0);
  std::vector<double> a(t.size()), mu(t.size());
  for (std::size_t k = 0; k < t.size(); ++k) {
    require_above("compare.t", t[k], 0.0);
    a[k] = std::cbrt(4 * D * t[k] * t[k]);
    mu[k] = std::min(mass / (rho * a[k]), kMuMax);
  }
  // From the largest lower end down: each integral is the one above it plus a piece.
  std::vector<std::size_t> order(t.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) { return mu[i] > mu[j]; });
  std::vector<double> n(t.size());
  double above = 0, from = kMuMax;
  for (std::size_t k : order) {
    above += shock_mass_integral(mu[k], from);
    from = mu[k];
    n[k] = L / a[k] * above;
  }
  return n;
}

double expected_shocks_above(double mass, double D, double L, double rho, double t) {
  return expected_shocks_above(mass, D, L, rho, std::span<const double>(&t, 1)).front();
}

}  // namespace shockgas::compare
