#pragma once
// The physics of the pressureless gas (the sticky gas's own continuum), in one
// place:
//
//     rho_t + (rho u)_x = 0,        (rho u)_t + (rho u^2)_x = 0,
//
// conserved variables U = (rho, m = rho u), u = m / rho (0 in vacuum).
//
// Riemann problem (Bouchut, "On zero pressure gas dynamics", 1994; Sheng & Zhang,
// Mem. AMS 654, 1999), states (rhoL, uL) | (rhoR, uR) at x = 0, solution in xi = x/t:
//  * uL < uR: two contact discontinuities at xi = uL and xi = uR with vacuum
//    between (the gas does not fill a gap: no pressure);
//  * uL = uR: one contact moving at u;
//  * uL > uR: a delta-shock at speed sigma, holding mass
//    m(t) = t (rhoL (uL - sigma) + rhoR (sigma - uR)) with momentum m sigma. The
//    generalised Rankine-Hugoniot relations d m/dt = [rho (u - sigma)] and
//    d(m sigma)/dt = [rho u (u - sigma)] give
//        sigma = (sqrt(rhoL) uL + sqrt(rhoR) uR) / (sqrt(rhoL) + sqrt(rhoR)),
//    i.e. the cluster moves at its momentum / mass. Only for rhoL = rhoR is this
//    the Burgers speed (uL + uR)/2.
#include <array>
#include <cmath>
#include <cstddef>

#include "shockgas/continuum/burgers_physics.hpp"

namespace shockgas::continuum {

// Velocity of a state: m / rho, and 0 in vacuum (rho <= 0).
inline double pressureless_velocity(double rho, double m) { return rho > 0 ? m / rho : 0.0; }

// Speed of the delta-shock between (rhoL, uL) and (rhoR, uR), uL > uR, not both vacuum.
inline double delta_shock_speed(double rhoL, double uL, double rhoR, double uR) {
  const double wl = std::sqrt(rhoL), wr = std::sqrt(rhoR);
  return (wl * uL + wr * uR) / (wl + wr);
}

// Mass of the delta-shock grown from Riemann data by time t (0 unless uL > uR).
inline double delta_shock_mass(double rhoL, double uL, double rhoR, double uR, double t) {
  if (!(uL > uR)) return 0.0;
  const double s = delta_shock_speed(rhoL, uL, rhoR, uR);
  return t * (rhoL * (uL - s) + rhoR * (s - uR));
}

// Which state xi = x/t sees (RiemannSide::fan here means the vacuum between the
// two contacts).
inline RiemannSide pressureless_riemann(double rhoL, double uL, double rhoR, double uR, double xi) {
  if (!(uL <= uR)) {  // delta-shock (a NaN also lands here, and propagates into the flux)
    const double s = delta_shock_speed(rhoL, uL, rhoR, uR);
    if (xi < s) return RiemannSide::left;
    if (xi > s) return RiemannSide::right;
    return RiemannSide::shock;
  }
  if (xi < uL) return RiemannSide::left;
  if (xi > uR) return RiemannSide::right;
  return uL == uR ? RiemannSide::left : RiemannSide::fan;  // on the contact: u = xi either side
}

// The pressureless gas for the finite-volume schemes. State = (rho, m).
struct PressurelessGas {
  static constexpr std::size_t components = 2;
  using State = std::array<double, 2>;  // {rho [mass/length], m = rho u [mass/time]}
  static constexpr const char* component_names[2] = {"rho", "momentum"};

  static double velocity(const State& u) { return pressureless_velocity(u[0], u[1]); }

  // Physical flux (rho u, rho u^2), computed from rho and u so that vacuum has none.
  static State flux(const State& u) {
    const double v = velocity(u), mass_flux = u[0] * v;
    return {mass_flux, mass_flux * v};
  }

  static double speed(const State& u) { return std::abs(velocity(u)); }

  // Godunov flux: the flux of the exact Riemann solution at x/t = 0; zero in the
  // vacuum between diverging states, the mean of both sides on a standing delta-shock.
  static State riemann_flux(const State& L, const State& R) {
    switch (pressureless_riemann(L[0], velocity(L), R[0], velocity(R), 0.0)) {
      case RiemannSide::left:
        return flux(L);
      case RiemannSide::right:
        return flux(R);
      case RiemannSide::fan:
        return {0.0, 0.0};
      case RiemannSide::shock:
        break;
    }
    const State fl = flux(L), fr = flux(R);
    return {0.5 * (fl[0] + fr[0]), 0.5 * (fl[1] + fr[1])};
  }
};

}  // namespace shockgas::continuum
