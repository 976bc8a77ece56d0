#include "shockgas/compare/white_noise_references.hpp"

#include <cmath>

#include "shockgas/compare/chernoff_table.hpp"
#include "shockgas/compare/cluster_velocity_law.hpp"
#include "shockgas/compare/eulerian_velocity_law.hpp"
#include "shockgas/compare/gauss_legendre.hpp"

namespace shockgas::compare {

bool is_white_noise_on_a_lattice(const InitialParams& p) {
  return p.positions == Positions::lattice &&
         (p.velocities == Velocities::uniform || p.velocities == Velocities::gaussian) && p.N > 0;
}

// int u^2 P_mass(u) du on [-5, 5] (P_mass(5) ~ 1e-40), 8-point Gauss-Legendre on
// panels of 0.05: the integrand is smooth, the rule exact to rounding long before.
double cluster_law_second_moment() {
  static const double moment = [] {
    const ClusterVelocityLaw& law = cluster_velocity_law();
    const GaussRule rule = gauss_legendre(8);
    constexpr double kUMax = 5.0, kPanel = 0.05;
    double sum = 0;
    for (int p = 0; p < static_cast<int>(2 * kUMax / kPanel); ++p)
      for (std::size_t i = 0; i < rule.x.size(); ++i) {
        const double u = -kUMax + kPanel * (p + 0.5 + 0.5 * rule.x[i]);
        sum += 0.5 * kPanel * rule.w[i] * u * u * law.mass_density(u);
      }
    return sum;
  }();
  return moment;
}

void prepare_white_noise_laws() {
  chernoff_log_g_table();
  cluster_velocity_law();
  cluster_law_second_moment();
}

std::optional<WhiteNoiseReferences> white_noise_references(const InitialParams& p) {
  if (!is_white_noise_on_a_lattice(p)) return std::nullopt;
  WhiteNoiseReferences r;
  r.D = white_noise_intensity(p);
  if (!(r.D > 0)) return std::nullopt;  // zero amplitude: no noise, no law
  r.length = domain_length(p);
  r.density = static_cast<double>(p.N) / r.length;  // unit masses
  const double s = eulerian_velocity_scale(r.D);    // (4 D)^(1/3)
  r.temperature_amplitude = s * s * cluster_law_second_moment();
  r.shock_count_coefficient = r.length * cluster_velocity_law().shock_density() / s;
  return r;
}

}  // namespace shockgas::compare
