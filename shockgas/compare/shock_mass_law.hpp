#pragma once
// The exact law of the shocks' masses in Burgers turbulence from white-noise
// initial velocity (the clusters of the sticky gas at r = 0), from the shock
// intensity of cluster_velocity_law.hpp: integrating n(alpha, beta) over
// alpha + beta = mu gives the number of shocks of mass in [mu, mu + dmu] per
// unit length,
//
//     N(mu) = 2 mu K(mu) (g * g)(mu),   (g * g)(mu) = int g(mu/2 + u) g(mu/2 - u) du,
//
// in the scaled units of that header (lengths and masses in units of
// a = (4 D t^2)^(1/3) at unit density). N(mu) ~ (2 / pi)^(1/2) mu^(-1/2) for
// mu -> 0 ((g * g)(0) = 2 int f = 2 and K's Brownian-excursion limit
// (2^(1/3) mu)^(-3/2) / (2 sqrt(pi))): many small shocks holding little mass; it
// falls like exp(-mu^3 / 6) for mu >> 1. Its integral is the shock density n_s = 2.1085
// and its first moment the mass, int mu N(mu) dmu = 1 (every particle is in a
// shock): both are checked in tests/compare/test_shock_mass_law.cpp.
//
// In a gas of mean density rho (mass per length) on a ring of length L, the
// expected number of shocks with mass in [m1, m2] at time t is
// (L / a) int_{m1 / (rho a)}^{m2 / (rho a)} N(mu) dmu.
#include <span>
#include <vector>

namespace shockgas::compare {

// N(mu) in scaled units. Throws InputError unless mu > 0.
double shock_mass_density(double mu);

// int_{mu1}^{mu2} N(mu) dmu, 0 <= mu1 <= mu2 (quadrature in sqrt(mu), where N dmu
// is smooth; N is taken as 0 beyond mu = 12, where it is below e^-288).
double shock_mass_integral(double mu1, double mu2);

// The expected number of shocks in each mass bin [m_j, m_(j+1)] (masses in the
// gas's units) on a ring of length L with mean density rho at time t, for white
// noise of intensity D (eulerian_velocity_law.hpp). Throws InputError unless the
// edges increase from >= 0 (>= 2 of them) and D, L, rho, t > 0.
std::vector<double> expected_shocks_in_mass_bins(std::span<const double> mass_edges, double D, double L,
                                                 double rho, double t);

// The expected number of shocks heavier than `mass` (the same gas and units):
// (L / a) int_{mass / (rho a)}^inf N(mu) dmu. Throws InputError unless mass >= 0
// and D, L, rho, t > 0.
double expected_shocks_above(double mass, double D, double L, double rho, double t);

// The same at each of the times t (> 0, any order), in one sweep of the
// quadrature from the largest mass unit's lower end to the cut-off: the cost of
// one call, not of one per time (each density value is an Airy sum and a
// convolution). Agrees with expected_shocks_above to the quadrature's error.
std::vector<double> expected_shocks_above(double mass, double D, double L, double rho,
                                          std::span<const double> t);

}  // namespace shockgas::compare
