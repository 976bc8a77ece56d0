#pragma once
// The reference problems of the work-precision charts (docs/performance.md), all
// on the periodic unit interval, each with its exact inviscid solution by
// Hopf-Lax (shockgas/continuum/hopf_lax.hpp):
//  * riemann:   v0 = 1 on [0, 1/2), 0 on [1/2, 1): a shock from x = 1/2 at speed 1/2
//               and a rarefaction from x = 0, to t = 0.4;
//  * sine_pre:  v0 = 0.5 + sin 2 pi x at t = 0.1, smooth (the shock forms at t = 1/2pi);
//  * sine_post: the same at t = 0.5, one shock at x = 0.5 + 0.5 t;
//  * noise:     white noise, v0 uniform on [-1, 1] on 64 equal pieces (seeded), at
//               t = 0.1: many shocks that have merged, like the gas's velocities.
#include <string>
#include <vector>

#include "shockgas/core/initial_condition.hpp"

namespace shockgas::studies {

struct Problem {
  std::string name;
  InitialField field;
  double t = 0;              // time of the comparison [time]
  bool shock_error = false;  // whether the shock-position error is measured (isolated shocks)
  double max_speed = 0;      // max |v0| [length/time]
  double spread = 0;         // max v0 - min v0 [length/time]
};

std::vector<Problem> reference_problems();
Problem problem_by_name(const std::string& name);  // throws InputError for an unknown name

}  // namespace shockgas::studies
