// The exact Riemann solutions and Godunov fluxes of Burgers + continuity and of
// the pressureless gas (burgers_physics.hpp, pressureless_physics.hpp). All
// expected values are exact in binary floating point unless a tolerance is given.
#include <gtest/gtest.h>

#include <cmath>

#include "shockgas/continuum/burgers_physics.hpp"
#include "shockgas/continuum/pressureless_physics.hpp"

namespace shockgas::continuum {
namespace {

TEST(BurgersRiemann, ShockMovesAtRankineHugoniotSpeed) {
  // vL = 1, vR = -0.5: s = (vL + vR)/2 = 0.25.
  EXPECT_EQ(burgers_shock_speed(1.0, -0.5), 0.25);
  EXPECT_EQ(burgers_riemann(1.0, -0.5, 0.2499).v, 1.0);
  EXPECT_EQ(burgers_riemann(1.0, -0.5, 0.2501).v, -0.5);
  EXPECT_EQ(burgers_riemann(1.0, -0.5, 0.25).side, RiemannSide::shock);
}

TEST(BurgersRiemann, RarefactionFanIsLinearInXOverT) {
  EXPECT_EQ(burgers_riemann(0.25, 1.0, 0.1).v, 0.25);
  EXPECT_EQ(burgers_riemann(0.25, 1.0, 0.5).v, 0.5);
  EXPECT_EQ(burgers_riemann(0.25, 1.0, 0.5).side, RiemannSide::fan);
  EXPECT_EQ(burgers_riemann(0.25, 1.0, 2.0).v, 1.0);
}

TEST(BurgersRiemann, TransonicFanHasZeroVelocityAtTheInterface) {
  const auto w = burgers_riemann(-1.0, 2.0, 0.0);
  EXPECT_EQ(w.v, 0.0);
  EXPECT_EQ(w.side, RiemannSide::fan);
  // Godunov flux 0 for v and for mass; the mean-speed upwind flux would give f(-1) = 0.5.
  const auto F = BurgersContinuity::riemann_flux({-1.0, 3.0}, {2.0, 5.0});
  EXPECT_EQ(F[0], 0.0);
  EXPECT_EQ(F[1], 0.0);
}

TEST(BurgersRiemann, GodunovFluxTakesTheUpwindSideOfTheWave) {
  // Shock moving right (s = 0.25 > 0): left flux (vL^2/2, rhoL vL).
  auto F = BurgersContinuity::riemann_flux({1.0, 2.0}, {-0.5, 7.0});
  EXPECT_EQ(F[0], 0.5);
  EXPECT_EQ(F[1], 2.0);
  // Shock moving left even though vL > 0 (s = -0.25): right flux.
  F = BurgersContinuity::riemann_flux({0.5, 2.0}, {-1.0, 7.0});
  EXPECT_EQ(F[0], 0.5);
  EXPECT_EQ(F[1], -7.0);
  // Standing shock: the mean of both one-sided fluxes.
  F = BurgersContinuity::riemann_flux({1.0, 2.0}, {-1.0, 4.0});
  EXPECT_EQ(F[0], 0.5);
  EXPECT_EQ(F[1], 0.5 * (2.0 - 4.0));
  // Supersonic rarefactions: fully upwind.
  F = BurgersContinuity::riemann_flux({0.5, 2.0}, {1.0, 7.0});
  EXPECT_EQ(F[1], 1.0);
  F = BurgersContinuity::riemann_flux({-1.0, 2.0}, {-0.5, 7.0});
  EXPECT_EQ(F[1], -3.5);
}

TEST(BurgersRiemann, ExactSolutionCarriesMassIntoTheDeltaShock) {
  const BurgersRiemannProblem p{1.0, 0.0, 4.0, 1.0, 0.3};
  // s = 0.5; the shock swallows rhoL (vL - s) + rhoR (s - vR) = 2 + 0.5 per unit time.
  EXPECT_DOUBLE_EQ(exact_shock_position(p, 0.4), 0.5);
  EXPECT_DOUBLE_EQ(exact_shock_mass(p, 0.4), 1.0);
  EXPECT_EQ(exact_density(p, 0.49, 0.4), 4.0);
  EXPECT_EQ(exact_density(p, 0.51, 0.4), 1.0);
  const BurgersRiemannProblem fan{-1.0, 1.0, 1.0, 1.0, 0.5};
  EXPECT_EQ(exact_density(fan, 0.6, 0.2), 0.0);
  EXPECT_EQ(exact_shock_mass(fan, 0.2), 0.0);
}

TEST(BurgersRiemann, ExactCellAveragesIntegrateTheFan) {
  // Fan from x0 = 0.5 with vL = -1, vR = 1 at t = 0.25 covers [0.25, 0.75]; v = (x - 0.5)/t.
  const BurgersRiemannProblem fan{-1.0, 1.0, 1.0, 1.0, 0.5};
  const auto v = exact_velocity_averages(fan, 1.0, 8, 0.25);
  // Cells of width 1/8: [0, .125) -> -1; [.25, .375) -> mean of (x - .5)/.25 = -0.75.
  // Tolerance: rounding of the antiderivative differences (a few ulps of O(1) / dx).
  EXPECT_NEAR(v[0], -1.0, 1e-14);
  EXPECT_NEAR(v[2], -0.75, 1e-14);
  EXPECT_NEAR(v[4], 0.25, 1e-14);
  EXPECT_NEAR(v[7], 1.0, 1e-14);
}

TEST(PressurelessRiemann, DeltaShockMovesAtMomentumOverMass) {
  // rhoL = 4, uL = 1, rhoR = 1, uR = 0: sigma = (2*1 + 1*0)/(2 + 1) = 2/3,
  // not the Burgers speed 1/2; mass 2 t, momentum 2 t * 2/3.
  const double s = delta_shock_speed(4.0, 1.0, 1.0, 0.0);
  EXPECT_DOUBLE_EQ(s, 2.0 / 3.0);
  const double t = 0.4, m = delta_shock_mass(4.0, 1.0, 1.0, 0.0, t);
  EXPECT_DOUBLE_EQ(m, 0.8);
  // Generalised Rankine-Hugoniot: momentum gained = t [rho u (u - sigma)] = m sigma.
  const double momentum = t * (4.0 * 1.0 * (1.0 - s) + 1.0 * 0.0 * (s - 0.0));
  EXPECT_DOUBLE_EQ(momentum / m, s);
  // Equal densities: the Burgers speed.
  EXPECT_DOUBLE_EQ(delta_shock_speed(2.0, 1.0, 2.0, -0.5), burgers_shock_speed(1.0, -0.5));
}

TEST(PressurelessRiemann, DivergingStatesLeaveVacuumWithNoFlux) {
  EXPECT_EQ(pressureless_riemann(1.0, -1.0, 1.0, 1.0, 0.0), RiemannSide::fan);
  const auto F = PressurelessGas::riemann_flux({1.0, -1.0}, {2.0, 2.0});
  EXPECT_EQ(F[0], 0.0);
  EXPECT_EQ(F[1], 0.0);
  // Both moving right: left flux (rho u, rho u^2) = (1.5, 0.75).
  const auto G = PressurelessGas::riemann_flux({3.0, 1.5}, {1.0, 2.0});
  EXPECT_EQ(G[0], 1.5);
  EXPECT_EQ(G[1], 0.75);
}

TEST(PressurelessRiemann, VacuumHasNoVelocityAndNoFlux) {
  EXPECT_EQ(PressurelessGas::velocity({0.0, 0.0}), 0.0);
  const auto F = PressurelessGas::riemann_flux({0.0, 0.0}, {0.0, 0.0});
  EXPECT_EQ(F[0], 0.0);
  // Gas moving left into vacuum on its left: the right state's flux.
  const auto G = PressurelessGas::riemann_flux({0.0, 0.0}, {2.0, -1.0});
  EXPECT_EQ(G[0], -1.0);
  EXPECT_EQ(G[1], 0.5);
}

}  // namespace
}  // namespace shockgas::continuum
