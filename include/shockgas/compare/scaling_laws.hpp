#pragma once
// The scaling laws the comparison measures against (Ben-Naim, Chen, Doolen &
// Redner, PRL 83, 4069 (1999); DESIGN.md §1), with eps = (1 - r) / 2:
//
//   t_dissip = 1 / eps          end of the effectively elastic regime, T ~ 1
//   t_stick  = eps^(-3/2)       end of homogeneous cooling, T ~ eps^-2 t^-2;
//                               beyond it T ~ t^(-2/3) (sticky gas)
//   n_shocks ~ N t^(-2/3)       clusters (= shocks) left at time t on a ring of
//                               N particles of unit spacing: clusters have mass
//                               ~ t^(2/3) (Burgers: shock spacing ~ t^(2/3))
//   z = v t^(1/3)               scaled velocity: P(v, t) = t^(1/3) Phi(z),
//                               Phi(z) ~ exp(-c |z|^3) in the tail
#include <cstddef>

namespace shockgas::compare {

// eps = (1 - r) / 2. Throws InputError unless 0 <= r <= 1.
double inelasticity(double r);
// 1 / eps (+infinity for r = 1).
double dissipation_time(double r);
// eps^(-3/2) (+infinity for r = 1).
double sticking_time(double r);

// N t^(-2/3): the expected number of shocks, up to an O(1) constant.
// Throws InputError unless N > 0 and t > 0.
double expected_shock_count(double N, double t);
// n_shocks / (N t^(-2/3)); constant in time in the sticky regime.
double shock_count_ratio(std::size_t n_shocks, double N, double t);

// z = v t^(1/3).
double scaled_velocity(double v, double t);

}  // namespace shockgas::compare
