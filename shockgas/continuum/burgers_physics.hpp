#pragma once
// The physics of the adhesion model, in one place: the inviscid Burgers equation
// with the continuity equation riding along,
//
//     v_t + (v^2/2)_x = 0,        rho_t + (rho v)_x = 0,
//
// its exact Riemann solution, and the Godunov flux built from it. Every
// finite-volume scheme of shockgas that solves Burgers sees only the struct
// BurgersContinuity (the interface of godunov_scheme.hpp); nothing else in the
// numerics knows the flux.
//
// Riemann problem v(x, 0) = vL for x < 0, vR for x > 0 (LeVeque, "Finite Volume
// Methods for Hyperbolic Problems", 2002, §11.2 and §12.2): the solution depends on
// xi = x/t only,
//  * vL > vR: a shock moving at the Rankine-Hugoniot speed s = (vL + vR)/2;
//  * vL <= vR: a rarefaction fan, v = xi for vL < xi < vR. When vL < 0 < vR the fan
//    is transonic and v = 0 at the interface: the Godunov flux is 0 there, where a
//    flux that only looks at the mean speed would keep an expansion shock.
// The density is carried by the same characteristics: upwind state outside the
// wave; inside a centred fan every fluid element comes from the single point
// x = 0, so the fan is vacuum (rho = 0); a shock holds a delta of mass (a
// delta-shock) fed by rho (v - s) from both sides.
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace shockgas::continuum {

// Which state of the Riemann solution a point xi = x/t sees.
enum class RiemannSide {
  left,   // the left state, unchanged
  right,  // the right state, unchanged
  fan,    // inside a rarefaction fan: v = xi, rho = 0 (vacuum)
  shock,  // exactly on a shock: traces from both sides (the flux is their mean)
};

struct BurgersRiemannSample {
  double v = 0;                          // velocity at xi [length/time]
  RiemannSide side = RiemannSide::left;  // where the density comes from
};

// Burgers flux f(v) = v^2 / 2.
inline double burgers_flux(double v) { return 0.5 * v * v; }

// Rankine-Hugoniot speed of a Burgers shock: s = [f]/[v] = (vL + vR) / 2.
inline double burgers_shock_speed(double vL, double vR) { return 0.5 * (vL + vR); }

// The exact Riemann solution of Burgers sampled at xi = x/t.
inline BurgersRiemannSample burgers_riemann(double vL, double vR, double xi) {
  if (!(vL <= vR)) {  // shock (a NaN also lands here, and propagates into the flux)
    const double s = burgers_shock_speed(vL, vR);
    if (xi < s) return {vL, RiemannSide::left};
    if (xi > s) return {vR, RiemannSide::right};
    return {vL, RiemannSide::shock};
  }
  if (xi <= vL) return {vL, RiemannSide::left};  // rarefaction (or vL == vR)
  if (xi >= vR) return {vR, RiemannSide::right};
  return {xi, RiemannSide::fan};
}

// Burgers + continuity as a system for the finite-volume schemes. State = (v, rho).
struct BurgersContinuity {
  static constexpr std::size_t components = 2;
  using State = std::array<double, 2>;  // {v [length/time], rho [mass/length]}
  static constexpr const char* component_names[2] = {"v", "rho"};

  // Physical flux (v^2/2, rho v).
  static State flux(const State& u) { return {burgers_flux(u[0]), u[1] * u[0]}; }

  // Fastest signal speed in a cell, |v|: sets the CFL time step.
  static double speed(const State& u) { return std::abs(u[0]); }

  // Godunov flux at an interface: the flux of the exact Riemann solution at
  // x/t = 0. The mass flux is rho_upwind * v(0): left density if the solution at
  // the interface is the left state (a shock with s > 0, or vL >= 0), right if it
  // is the right state, 0 inside a transonic fan (v(0) = 0), and the mean of both
  // one-sided fluxes on a stationary shock (s = 0). The transonic zero is also
  // the smooth solution's rho v at a sonic point; what a first-order scheme makes
  // of the density there is in godunov.hpp.
  static State riemann_flux(const State& L, const State& R) {
    const BurgersRiemannSample w = burgers_riemann(L[0], R[0], 0.0);
    switch (w.side) {
      case RiemannSide::left:
        return flux(L);
      case RiemannSide::right:
        return flux(R);
      case RiemannSide::fan:
        return {burgers_flux(w.v), 0.0};
      case RiemannSide::shock:
        break;
    }
    const State fl = flux(L), fr = flux(R);
    return {0.5 * (fl[0] + fr[0]), 0.5 * (fl[1] + fr[1])};
  }
};

// The exact solution of one Riemann problem of Burgers + continuity, with the
// jump at x0 at t = 0 (for tests and the riemann scene; not used by the schemes).
struct BurgersRiemannProblem {
  double vL = 1, vR = 0;      // velocities left and right of the jump [length/time]
  double rhoL = 1, rhoR = 1;  // densities left and right [mass/length], >= 0
  double x0 = 0;              // position of the jump at t = 0 [length]
};

// v(x, t) (on the shock itself the left value).
double exact_velocity(const BurgersRiemannProblem& p, double x, double t);
// The absolutely continuous part of rho(x, t): upwind density, 0 inside a fan.
double exact_density(const BurgersRiemannProblem& p, double x, double t);
// Position of the shock at time t (x0 + s t), or of the fan's centre x0.
double exact_shock_position(const BurgersRiemannProblem& p, double t);
// Mass held in the delta-shock at time t: t (rhoL (vL - s) + rhoR (s - vR)); 0 for a fan.
double exact_shock_mass(const BurgersRiemannProblem& p, double t);
// Exact cell averages of v on `cells` cells of [0, length) (no periodic wrap),
// from the antiderivative of the piecewise-linear solution.
std::vector<double> exact_velocity_averages(const BurgersRiemannProblem& p, double length, std::size_t cells,
                                            double t);

}  // namespace shockgas::continuum
