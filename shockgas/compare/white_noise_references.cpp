#include "shockgas/compare/white_noise_references.hpp"

#include <cmath>

#include "shockgas/compare/cluster_velocity_law.hpp"
#include "shockgas/compare/eulerian_velocity_law.hpp"

namespace shockgas::compare {

bool is_white_noise_on_a_lattice(const InitialParams& p) {
  return p.positions == Positions::lattice &&
         (p.velocities == Velocities::uniform || p.velocities == Velocities::gaussian) && p.N > 0;
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
