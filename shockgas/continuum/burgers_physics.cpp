// The exact solution of one Burgers + continuity Riemann problem (see
// burgers_physics.hpp for the wave structure; LeVeque 2002, §11.2).
#include "shockgas/continuum/burgers_physics.hpp"

#include <cassert>

namespace shockgas::continuum {

double exact_velocity(const BurgersRiemannProblem& p, double x, double t) {
  if (t <= 0) return x < p.x0 ? p.vL : p.vR;
  return burgers_riemann(p.vL, p.vR, (x - p.x0) / t).v;
}

double exact_density(const BurgersRiemannProblem& p, double x, double t) {
  if (t <= 0) return x < p.x0 ? p.rhoL : p.rhoR;
  switch (burgers_riemann(p.vL, p.vR, (x - p.x0) / t).side) {
    case RiemannSide::left:
    case RiemannSide::shock:
      return p.rhoL;
    case RiemannSide::right:
      return p.rhoR;
    case RiemannSide::fan:
      break;
  }
  return 0.0;
}

double exact_shock_position(const BurgersRiemannProblem& p, double t) {
  return p.vL > p.vR ? p.x0 + burgers_shock_speed(p.vL, p.vR) * t : p.x0;
}

double exact_shock_mass(const BurgersRiemannProblem& p, double t) {
  if (!(p.vL > p.vR)) return 0.0;
  const double s = burgers_shock_speed(p.vL, p.vR);
  return t * (p.rhoL * (p.vL - s) + p.rhoR * (s - p.vR));
}

namespace {

// V(x) = integral of v(y, t) dy from x0 to x, for the piecewise-linear solution.
double velocity_antiderivative(const BurgersRiemannProblem& p, double x, double t) {
  const double y = x - p.x0;
  if (p.vL > p.vR || t <= 0) {  // shock (or the initial jump)
    const double ys = p.vL > p.vR ? burgers_shock_speed(p.vL, p.vR) * t : 0.0;
    return y <= ys ? p.vL * y : p.vL * ys + p.vR * (y - ys);
  }
  const double a = p.vL * t, b = p.vR * t;  // fan edges relative to x0
  if (y <= a) return p.vL * y;
  const double at_a = p.vL * a;
  if (y < b) return at_a + (y * y - a * a) / (2 * t);
  return at_a + (b * b - a * a) / (2 * t) + p.vR * (y - b);
}

}  // namespace

std::vector<double> exact_velocity_averages(const BurgersRiemannProblem& p, double length, std::size_t cells,
                                            double t) {
  assert(cells > 0 && length > 0);
  std::vector<double> v(cells);
  const double dx = length / static_cast<double>(cells);
  double left = velocity_antiderivative(p, 0.0, t);
  for (std::size_t i = 0; i < cells; ++i) {
    const double right = velocity_antiderivative(p, static_cast<double>(i + 1) * dx, t);
    v[i] = (right - left) / dx;
    left = right;
  }
  return v;
}

}  // namespace shockgas::continuum
