#pragma once
// Viscous Burgers v_t + (v^2/2)_x = nu v_xx by explicit (forward Euler) time
// stepping on a periodic grid: the scheme whose diffusive step limit the
// stability charts measure (docs/performance.md), next to CVODE / ARKODE, which
// treat the diffusion implicitly and have no such limit.
//
//     v_i <- v_i - (dt/h) (F_{i+1/2} - F_{i-1/2}) + (nu dt / h^2) (v_{i+1} - 2 v_i + v_{i-1}),
//
// F = the exact Godunov flux of Burgers (burgers_physics.hpp). Von Neumann
// analysis of the frozen-coefficient scheme (e.g. Hirsch, "Numerical Computation
// of Internal and External Flows", vol. 1, §8.3): stable, and monotone, iff
//
//     dt (|v|/h + 2 nu/h^2) <= 1,
//
// i.e. dt <= h^2 / (2 nu) / (1 + |v| h / (2 nu)); for a resolved grid
// (|v| h / 2 nu << 1) this is the diffusive limit dt <= h^2 / 2 nu. Beyond it the
// highest mode grows by |1 - 4 nu dt / h^2| per step.
#include <cstddef>
#include <vector>

namespace shockgas::continuum {

struct ExplicitViscousParams {
  double nu = 1e-2;              // viscosity [length^2/time], > 0
  double dt = 1e-4;              // fixed time step [time], > 0
  std::size_t steps = 1000;      // number of steps, >= 1
  double blow_up_factor = 10.0;  // stop once max|v| exceeds this times max|v0| [1], > 1
};

struct ExplicitViscousResult {
  std::vector<double> v;       // cell averages after the steps taken [length/time]
  std::size_t steps = 0;       // steps taken (fewer than asked if it blew up)
  bool blew_up = false;        // max|v| passed blow_up_factor * max|v0| (or turned non-finite)
  double max_abs_v = 0;        // max|v| at the end [length/time]
  double total_variation = 0;  // sum |v_{i+1} - v_i| at the end (periodic) [length/time]
};

// Periodic grid of v0.size() cells of width h on [0, h v0.size()).
// Throws InputError for nu <= 0, dt <= 0, steps = 0, h <= 0 or fewer than 3 cells.
ExplicitViscousResult explicit_viscous_burgers(const std::vector<double>& v0, double h,
                                               const ExplicitViscousParams& p);

// The largest stable step of the frozen-coefficient analysis above for speed
// max_speed: 1 / (max_speed / h + 2 nu / h^2) [time].
double explicit_viscous_dt_limit(double max_speed, double h, double nu);

// Total variation sum_i |v_{i+1} - v_i| of a periodic grid function.
double periodic_total_variation(const std::vector<double>& v);

}  // namespace shockgas::continuum
