#pragma once
// Shocks of a continuum field: the continuum side of "shocks are clusters".
//
// Where the solver knows its shocks (ContinuumResult::has_shocks, e.g. the exact
// Hopf-Lax solver) its list is used as is. Otherwise shocks are found in the
// cell averages of v and rho on the periodic grid:
//
//  1. A compressive interface is one with v_{i+1} - v_i < 0 (between shocks the
//     profile is a ramp of slope ~ 1/t > 0, so every drop is compression).
//  2. A run of consecutive compressive interfaces is one compression region (a
//     shock smeared over a few cells by the scheme or the viscosity counts
//     once). A run wider than max_width_cells is cut to the window of that many
//     interfaces with the largest total drop (a shock at the foot of a smooth
//     compression keeps only its steep part).
//  3. The region's cells C = both cells of every interface in it. Outside it,
//     the ramps on either side are extrapolated into it with the mean of the
//     neighbouring one-sided slopes s (each clamped at >= 0):
//         v_L(x) = v_a + s (x - x_a),   v_R(x) = v_b + s (x - x_b)
//     (a, b: the cells just left and right of C). The jump J = v_R - v_L is
//     then constant, and the shock position x_s is where a step from v_L to v_R
//     has the same integral of v over C as the data (conservation of v, the
//     Burgers conserved variable):
//         x_s = x_left_edge(C) + ( int_C v_R dx - dx sum_{i in C} v_i ) / J.
//     For a piecewise-linear profile with ramps of equal slope (the exact
//     sawtooth) and a shock anywhere in C this is exact.
//  4. Kept if -J >= min_jump and the data themselves drop across the whole run
//     of step 2 (before any cut to max_width_cells) by at least min_jump / 2: where two ramps of different
//     slope meet (the edge of a rarefaction fan) the extrapolation alone makes a jump, and a drop of rounding
//     size (1e-16) there is no shock. Mass = excess mass over the ramps' background,
//         mass = dx sum_{i in C} (rho_i - (rho_a + rho_b) / 2)   (>= 0),
//     exact for a delta shock on a constant background. Velocity = the
//     Rankine-Hugoniot speed of Burgers, (v_L(x_s) + v_R(x_s)) / 2.
//
// Shocks closer than about four cells merge or bias each other; the grid must
// resolve the spacing between shocks.
#include <cstddef>
#include <vector>

#include "shockgas/continuum/field.hpp"

namespace shockgas::compare {

struct ShockDetectionParams {
  double min_jump = 0;              // smallest |v_R - v_L| counted as a shock [length/time];
                                    // 0 = automatic: 5% of (max v - min v) of the field
  std::size_t max_width_cells = 8;  // widest compression region taken as one shock [cells], >= 1
};

// Shocks of v, rho on the uniform periodic grid of `v.size()` cells of
// [0, length), sorted by x (in [0, length)). rho may be empty (mass = 0).
// Throws InputError if length <= 0, v has fewer than 5 cells, sizes differ or
// params are out of range.
std::vector<continuum::Shock> detect_shocks(const std::vector<double>& v, const std::vector<double>& rho,
                                            double length, const ShockDetectionParams& params = {});

// The solver's own shock list if it has one, else detect_shocks on its fields.
std::vector<continuum::Shock> find_shocks(const continuum::ContinuumResult& field,
                                          const ShockDetectionParams& params = {});

}  // namespace shockgas::compare
