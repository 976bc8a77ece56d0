#pragma once
// The sawtooth: between shocks the velocity of the sticky gas / inviscid
// Burgers is the ramp v(x, t) = (x - q) / t with q (nearly) constant, so each
// ramp has slope 1/t and slope * t = 1 (docs/design.md §1; the paper's Fig. 5).
//
// For each ramp between consecutive shocks X_k < X_{k+1} on the ring (the last
// ramp runs from X_{K-1} across x = L to X_0 + L) the slope is fitted by
// weighted least squares of v against the unrolled cell centre x (Eigen, via
// fit_line), using only cells whose centres are at least
// (skip_cells + 1/2) dx from both shocks, so a shock smeared over a few cells
// does not bend the fit.
#include <cstddef>
#include <vector>

#include "shockgas/compare/statistics.hpp"

namespace shockgas::compare {

struct SawtoothParams {
  std::size_t skip_cells = 2;  // cells skipped beside each shock, beyond the shock's own cell [cells]
  std::size_t min_cells = 3;   // ramps with fewer usable cells are not fitted [cells], >= 2
};

struct RampFit {
  std::size_t left_shock = 0;  // index of the shock at its left end (the right one is the next)
  double x_begin = 0;          // left shock position [length]
  double x_end = 0;            // right shock position, unrolled (> x_begin; may exceed L) [length]
  std::size_t cells = 0;       // cells used in the fit
  double slope = 0;            // dv/dx [1/time]
  double slope_error = 0;      // its least-squares standard error [1/time]
  double slope_times_t = 0;    // slope * t [1]; theory 1
};

struct SawtoothFit {
  std::vector<RampFit> ramps;  // ramps with at least min_cells usable cells, in shock order
  Quartiles slope_times_t;     // quartiles of slope * t over ramps; NaN if no ramp
};

// v: cell averages on `v.size()` uniform cells of [0, length); t: time of the
// field; shock_x: shock positions in [0, length) (any order); weights: per-cell
// fit weights (e.g. the deposited mass; 0 excludes a cell), empty = all 1.
// Throws InputError if length or t <= 0, sizes differ or min_cells < 2.
SawtoothFit fit_sawtooth_slopes(const std::vector<double>& v, double length, double t,
                                std::vector<double> shock_x, const SawtoothParams& params = {},
                                const std::vector<double>& weights = {});

// The same with ramps given as intervals between objects of finite extent (the
// clusters of an r > 0 gas spread over ~ delta t): ramp k runs from the right
// end of object k to the left end of object k + 1 (the last one wraps).
// extents: [left, right] of each object, left in [0, length), right >= left
// (unrolled past length if the object wraps), sorted by left; they must not
// overlap. A point object (left = right) gives fit_sawtooth_slopes.
struct Extent {
  double left = 0;   // [length]
  double right = 0;  // [length]
};
SawtoothFit fit_sawtooth_between(const std::vector<double>& v, double length, double t,
                                 const std::vector<Extent>& extents, const SawtoothParams& params = {},
                                 const std::vector<double>& weights = {});

}  // namespace shockgas::compare
