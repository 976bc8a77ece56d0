// The semi-discretisation of viscous Burgers + continuity (see viscous_mol.hpp).
#include <cstddef>

#include "shockgas/continuum/burgers_physics.hpp"
#include "shockgas/continuum/viscous_mol.hpp"

namespace shockgas::continuum {

namespace {

// Periodic index arithmetic on the interleaved state: v of cell i at y[2i], rho at y[2i+1].
struct Periodic {
  std::size_t n;
  std::size_t operator()(std::size_t i, long offset) const {
    const long m = static_cast<long>(n);
    return static_cast<std::size_t>(((static_cast<long>(i) + offset) % m + m) % m);
  }
};

// Fourth-order face value v_{i+1/2} from the cell averages v_{i-1..i+2}.
double face_velocity(std::span<const double> y, const Periodic& at, std::size_t i) {
  return (7.0 * (y[2 * i] + y[2 * at(i, 1)]) - (y[2 * at(i, -1)] + y[2 * at(i, 2)])) / 12.0;
}

// Fourth-order h^2 v_xx of the cell averages: (-v_{i+2} + 16 v_{i+1} - 30 v_i + 16 v_{i-1} - v_{i-2}) / 12.
double second_difference(std::span<const double> y, const Periodic& at, std::size_t i) {
  return (-y[2 * at(i, 2)] + 16.0 * y[2 * at(i, 1)] - 30.0 * y[2 * i] + 16.0 * y[2 * at(i, -1)] -
          y[2 * at(i, -2)]) /
         12.0;
}

}  // namespace

void viscous_advection_rhs(const ViscousBurgersGrid& g, std::span<const double> y, std::span<double> ydot) {
  const Periodic at{g.cells};
  const double inv_h = 1.0 / g.h;
  // Flux through the left face of cell 0 (= right face of cell n-1), then sweep right.
  const std::size_t last = g.cells - 1;
  double vf = face_velocity(y, at, last);
  double left_v = burgers_flux(vf), left_rho = vf * (vf > 0 ? y[2 * last + 1] : y[1]);
  for (std::size_t i = 0; i < g.cells; ++i) {
    const std::size_t r = at(i, 1);
    vf = face_velocity(y, at, i);
    const double right_v = burgers_flux(vf), right_rho = vf * (vf > 0 ? y[2 * i + 1] : y[2 * r + 1]);
    ydot[2 * i] = -(right_v - left_v) * inv_h;
    ydot[2 * i + 1] = -(right_rho - left_rho) * inv_h;
    left_v = right_v;
    left_rho = right_rho;
  }
}

void viscous_diffusion_rhs(const ViscousBurgersGrid& g, std::span<const double> y, std::span<double> ydot) {
  const Periodic at{g.cells};
  const double c = g.nu / (g.h * g.h);
  for (std::size_t i = 0; i < g.cells; ++i) {
    ydot[2 * i] = c * second_difference(y, at, i);
    ydot[2 * i + 1] = 0.0;
  }
}

void viscous_burgers_rhs(const ViscousBurgersGrid& g, std::span<const double> y, std::span<double> ydot) {
  viscous_advection_rhs(g, y, ydot);
  const Periodic at{g.cells};
  const double c = g.nu / (g.h * g.h);
  for (std::size_t i = 0; i < g.cells; ++i) ydot[2 * i] += c * second_difference(y, at, i);
}

}  // namespace shockgas::continuum
