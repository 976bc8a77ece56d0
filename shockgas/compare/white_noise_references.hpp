#pragma once
// The exact references of a run that starts from white noise on a lattice
// (i.i.d. velocities, uniform or Gaussian: eulerian_velocity_law.hpp), in the
// gas's own units, for the plots and the report to be drawn against. Each is
// the inviscid limit -- Burgers turbulence, the sticky gas at r = 0 -- that the
// inelastic gas approaches in its sticky regime, t_stick << t << N^(3/2):
//
//   temperature:  T t^(2/3) -> (4 D)^(2/3) E_mass u^2 = 0.2129 for D = 1/3
//                 (cluster_velocity_law.hpp: E_mass u^2 = 0.17571);
//   shock count:  n(t) = L n_s (4 D)^(-1/3) t^(-2/3) = 1.916 N t^(-2/3) for D = 1/3,
//                 L = N (n_s = 2.1085 shocks per length a = (4 D t^2)^(1/3));
//   velocities:   the mass-weighted law of z = (v - U) t^(1/3) (cluster_law_on_bins);
//   masses:       the shocks' mass law (shock_mass_law.hpp).
//
// The shock count includes the many small shocks (N(mu) ~ mu^(-1/2)); a lattice
// gas cannot hold those lighter than a particle, so its count of clusters of two
// or more particles sits a few per cent below (docs/paper.md: 1.97 against 2.108
// per a at N = 10^6, t = 1000).
#include <optional>

#include "shockgas/core/initial_condition.hpp"

namespace shockgas::compare {

struct WhiteNoiseReferences {
  double D = 0;                        // intensity sigma^2 l [length^3/time^2]
  double length = 0;                   // L [length]
  double density = 0;                  // mean mass per length [mass/length]
  double temperature_amplitude = 0;    // T t^(2/3) of the sticky gas [length^2/time^(4/3)]
  double shock_count_coefficient = 0;  // C in n(t) = C t^(-2/3) [time^(2/3)]
};

// Whether p's initial condition is white noise on a lattice: positions
// "lattice", velocities "uniform" or "gaussian", N > 0.
bool is_white_noise_on_a_lattice(const InitialParams& p);

// The references of p's initial condition, or nothing when it is not white
// noise on a lattice or has no noise (amplitude 0).
std::optional<WhiteNoiseReferences> white_noise_references(const InitialParams& p);

}  // namespace shockgas::compare
