#pragma once
// The theory the measurements are held against, in one place, each law with its
// reference. BCDR = Ben-Naim, Chen, Doolen & Redner, "Shock-like dynamics of
// inelastic gases", PRL 83, 4069 (1999); its equations are numbered as there.
// Units: the initial mean spacing x0 = L / N, the typical initial velocity v0,
// time x0 / v0 (docs/design.md §6); eps = (1 - r) / 2 (BCDR eq. 1).
//
// Cooling law (BCDR eq. 3):
//   T ~ 1                   t << t_dissip = 1/eps        (effectively elastic)
//   T ~ eps^-2 t^-2         t_dissip << t << t_stick      (homogeneous cooling,
//                           eq. 2: T = (1 + A eps t)^-2 with A of order one)
//   T ~ t^(-2/3)            t_stick = eps^(-3/2) << t << N^(3/2)   (the sticky gas,
//                           amplitude of order one and independent of r; the two
//                           meet at t_stick, where T ~ eps; Carnevale, Pomeau &
//                           Young, PRL 64, 2913 (1990); Frachebourg, PRL 82, 1502 (1999))
//   T ~ 1/N                 t >> N^(3/2)                  (one cluster left)
// Clusters (= shocks) of the sticky regime have mass ~ t^(2/3), so a ring of N
// particles holds ~ N t^(-2/3) of them (BCDR; Burgers: shock spacing ~ t^(2/3)).
// Velocities: P(v, t) = t^(1/3) Phi(z), z = v t^(1/3) (BCDR eq. 4), with the tail
// Phi(z) ~ exp(-c |z|^3) (BCDR eq. 6; Frachebourg & Martin, J. Fluid Mech. 417,
// 323 (2000)). Between shocks v = (x - q) / t (BCDR eq. 7): slope * t = 1.
// The threshold method is valid while v ~ t^(-1/3) >> delta: t << delta^-3.
//
// Three particles on a line without a threshold (delta = 0) collapse -- infinitely
// many collisions in a finite time -- for r < 7 - 4 sqrt(3) and escape above it
// (Bernu & Mazighi, J. Phys. A 23, 5745 (1990); McNamara & Young, Phys. Fluids A
// 4, 496 (1992)).
//
// Waves of the inviscid Burgers equation (Whitham, Linear and Nonlinear Waves,
// 1974, ch. 2): a smooth v0 breaks -- its first shock forms -- at
// t* = 1 / max(-v0'), where the characteristics from the steepest descent of v0
// first cross. An isolated N-wave keeps the area A of each lobe (int v dx over
// it) and its amplitude decays as sqrt(2 A / t); a periodic sawtooth of period
// l decays as l / (2 t).
#include <cstddef>
#include <functional>

namespace shockgas::compare {

inline constexpr double kHomogeneousCoolingExponent = -2.0;   // T ~ t^-2 (eq. 3)
inline constexpr double kStickyCoolingExponent = -2.0 / 3.0;  // T ~ t^(-2/3) (eq. 3)
inline constexpr const char* kStickyCoolingExponentText = "-2/3";
inline constexpr double kVelocityScalingExponent = 1.0 / 3.0;  // z = v t^(1/3) (eq. 4)
inline constexpr double kTailExponent = 3.0;                   // Phi ~ exp(-c |z|^3) (eq. 6)
inline constexpr double kSawtoothSlopeTimesT = 1.0;            // v = (x - q) / t (eq. 7)

// Three particles; waves.
inline constexpr double kThreeParticleCollapseR = 0.071796769724490825;  // 7 - 4 sqrt(3)
inline constexpr double kNWaveAmplitudeExponent = -0.5;                  // amplitude sqrt(2 A / t)
inline constexpr double kSawtoothAmplitudeExponent = -1.0;               // amplitude l / (2 t)

// eps = (1 - r) / 2. Throws InputError unless 0 <= r <= 1.
double inelasticity(double r);
// 1 / eps (+infinity for r = 1).
double dissipation_time(double r);
// eps^(-3/2) (+infinity for r = 1).
double sticking_time(double r);

// The homogeneous-cooling law (1 + eps t)^-2 (eq. 2 with A = 1), and the sticky
// law t^(-2/3) with amplitude 1: each up to its constant of order one.
double homogeneous_cooling_temperature(double r, double t);
double sticky_gas_temperature(double t);

// t^(2/3): the typical cluster mass of the sticky regime [particle masses].
double typical_cluster_mass(double t);
// N t^(-2/3): the expected number of shocks, up to an O(1) constant.
// Throws InputError unless N > 0 and t > 0.
double expected_shock_count(double N, double t);
// n_shocks / (N t^(-2/3)); constant in time in the sticky regime.
double shock_count_ratio(std::size_t n_shocks, double N, double t);

// The mass below which the comparison counts neither clusters nor shocks, in
// particle masses, when compare.min_cluster_particles = 0: a tenth of the
// typical cluster mass, and at least 2, so that a lone particle or a pair of free
// particles is not a cluster: max(2, t^(2/3) / 10).
double automatic_min_cluster_particles(double t);

// z = v t^(1/3).
double scaled_velocity(double v, double t);

// delta^-3: the time up to which the threshold method can be trusted (+infinity for delta = 0).
double validity_time(double delta);

// t* = 1 / max(-v0') of a velocity v0 on [0, length) (periodic), the slope taken
// by centred differences on 2^16 points: relative error O((h / wavelength)^2),
// 1.5e-9 for a sine of period 1 (its steepest point falls between samples).
// +infinity where v0 nowhere decreases; 0 where the steepest drop is a jump
// (its difference halves over the two spacings around it, as J / h does and a
// slope does not; a smooth feature narrower than about h counts as one): the
// shock is there at t = 0 (it read h / J = 1e-5, a number of the sampling).
double breaking_time(const std::function<double(double)>& v0, double length);

}  // namespace shockgas::compare
