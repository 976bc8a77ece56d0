#pragma once
// The exact one-point law of the Eulerian velocity of Burgers turbulence from
// white-noise initial velocity, in the units shockgas plots:
//
//     z = (v(x, t) - U) t^(1/3)  has the law of  (4 D)^(1/3) Z,
//
// Z Chernoff's variable (chernoff.hpp), U the mean velocity, D the intensity of
// the white noise: Psi0(q) - U q is a random walk with Var = D q.
//
// Derivation. The inviscid solution is the Hopf-Lax formula
//     v(x, t) = (x - q*) / t,   q* = argmin_q [ (x - q)^2 / (2t) + Psi0(q) ],   Psi0' = v0.
// A Galilean shift removes U (v - U is the solution from v0 - U at x - U t), and
// the law of v at a fixed x does not depend on x (stationarity), so take U = 0,
// x = 0. On scales long against the spacing Psi0 = sqrt(D) B with B a two-sided
// standard Brownian motion. Scale q = a s: q^2/(2t) = a^2 s^2/(2t), and
// sqrt(D) B(a s) has the law of sqrt(D a) W(s). With a^(3/2) = 2 t sqrt(D),
// i.e. a = (4 D t^2)^(1/3), both terms carry the factor sqrt(D a):
//     q* / a = argmin_s [ s^2 + W(s) ] = argmax_s [ -W(s) - s^2 ]  ~  Z,
// (-W is again a Brownian motion), so v = -q*/t ~ (a / t) Z (Z is symmetric) and
//     v t^(1/3) ~ (4 D)^(1/3) Z,   density  f(z / s) / s,   s = (4 D)^(1/3),
//     <z^2> = (4 D)^(2/3) E Z^2 = 0.2635596 (4 D)^(2/3).
// White noise has an intensity, not a variance: for i.i.d. velocities of
// variance sigma^2 on a lattice of spacing l, Var Psi0(q) = sigma^2 l q, so
// D = sigma^2 l. For the gas's uniform velocities on [-1, 1] at unit spacing,
// D = 1/3, s = (4/3)^(1/3) = 1.10064 and <z^2> = 0.31928.
//
// Validity: the Brownian limit needs a >> l (t >> l / sigma: many particles per
// Lagrangian interval), the ring needs a << L; then the corrections are those
// of a random walk against Brownian motion at scale a (Donsker), and of the
// Brownian bridge that a ring's mean-free potential is (~ a / L).
// The law is the one-point law at a fixed Eulerian point (volume-weighted); the
// mass-weighted law of the clusters' velocities (the paper's Fig. 4) differs.
#include <cstddef>
#include <functional>
#include <span>
#include <vector>

#include "shockgas/continuum/field.hpp"
#include "shockgas/core/initial_condition.hpp"

namespace shockgas::compare {

// D = sigma^2 l. Throws InputError unless velocity_variance >= 0 and spacing > 0.
double white_noise_intensity(double velocity_variance, double spacing);

// D of a scene's initial velocities: sigma^2 = amplitude^2 / 3 ("uniform") or
// amplitude^2 ("gaussian"), l = L / N. Throws InputError for other velocities
// (not white noise) and for positions other than "lattice".
double white_noise_intensity(const InitialParams& p);

// s = (4 D)^(1/3): z = s u for every law of cluster_velocity_law.hpp too.
// Throws InputError unless D > 0.
double eulerian_velocity_scale(double D);

// Bin means of a law of z = s u given through its integral in u:
// integral(a, b) = int_a^b P(u) du, mean_j = integral(e_j / s, e_(j+1) / s) / (e_(j+1) - e_j).
// Throws InputError unless the edges increase (>= 2 of them).
std::vector<double> scaled_law_on_bins(std::span<const double> z_edges, double s,
                                       const std::function<double(double, double)>& integral);

// The law of z: density f(z/s)/s, CDF, p-quantile.
double eulerian_velocity_density(double z, double D);
double eulerian_velocity_cdf(double z, double D);
double eulerian_velocity_quantile(double p, double D);

// The law averaged over the bins of z_edges, (F(b) - F(a)) / (b - a): what a
// histogram normalised as a density of z (velocity_distribution.hpp) shows
// when it follows the law. Throws InputError unless the edges increase (>= 2).
std::vector<double> eulerian_law_on_bins(std::span<const double> z_edges, double D);

// The density on `points` equally spaced z in [-z_max, z_max], for a curve.
struct DensityCurve {
  std::vector<double> z;
  std::vector<double> density;
};
DensityCurve eulerian_law_curve(double D, double z_max, std::size_t points);

// Scaled point velocities z = (v(x_i) - <v>) t^(1/3) of an exact (hopf_lax)
// field at the centres x_i of every `stride`-th cell, i = 0, stride, ...
// Between shocks the field is a ramp of slope 1/t, so a cell's average is its
// centre value once the listed shocks inside the cell are taken out (their
// positions and jumps are known). <v> is the mean of the cell averages (= U,
// which the flow conserves). A field of point masses does not list the clusters
// of one body (jump 1/t): they move v by at most 1/t, z by t^(-2/3).
// Throws InputError unless the field knows its shocks, t > 0 and stride >= 1.
std::vector<double> eulerian_scaled_samples(const continuum::ContinuumResult& field, std::size_t stride);

}  // namespace shockgas::compare
