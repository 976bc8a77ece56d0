#pragma once
// How a wave evolves: measurements on one solver's fields at a series of times
// (shockgas/continuum/series.hpp), to be held against the laws of theory.hpp.
//
// Per frame: the amplitude (max v - min v) / 2; the steepest slope, the least
// (v_{i+1} - v_i) / dx over the periodic grid; the areas of the lobes of v above
// and below its mean U (conserved, U = int v dx / L), A+ = int (v - U)^+ dx and
// A- = int (v - U)^- dx; the number of shocks (compare::find_shocks).
//
// Shock formation. While the solution is smooth, along the characteristic from
// the steepest descent of v0 (slope v0' = -1/t*) the slope is v0' / (1 + v0' t),
// and no other point is steeper, so
//     -1 / min_x dv/dx (t) = t* - t,
// a straight line in t that reaches zero at the breaking time t* (theory.hpp).
// The measured t* is the zero of the least-squares line through (t, -1/slope)
// over the smooth frames (before the first one holding a shock) whose steepest
// cell-to-cell change is at most kResolvedStep of the field's range: there the
// cell averages still resolve the slope (on the sine at 512 cells -1/slope is
// t* - t to 0.1% of t* at that step, 2% at a fifth of the range).
// The first frame holding a shock brackets t* from above, the frame before it
// from below; a frame at t = 0 (the initial cell averages, whose shocks no
// solver has found yet) is neither.
//
// Decay. The amplitude is fitted as a power of t over [t_from, t_last] with
// t_from = max(t_last / fit_window, fit_t_min, the first frame holding a shock):
// never across the breaking, and from where the caller's law holds (an
// isolated N-wave: -1/2, its lobe areas kept; a periodic sawtooth: -1; where
// they hold: theory_scope.hpp).
#include <cstddef>
#include <limits>
#include <optional>
#include <vector>

#include "shockgas/compare/cooling_law.hpp"
#include "shockgas/compare/shock_detection.hpp"
#include "shockgas/continuum/field.hpp"

namespace shockgas::compare {

inline constexpr double kResolvedStep = 0.05;  // see above [1]

struct FieldEvolution {
  static constexpr double kNone = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> t;                     // frame times [time]
  std::vector<double> amplitude;             // (max v - min v) / 2 [length/time]
  std::vector<double> steepest_slope;        // min (v_{i+1} - v_i) / dx [1/time]
  std::vector<double> positive_area;         // A+ [length^2/time]
  std::vector<double> negative_area;         // A- (<= 0) [length^2/time]
  std::vector<double> shocks;                // shocks in the frame [1]
  std::vector<double> formation_fit;         // 1 for the frames in the breaking-time fit, else 0 [1]
  double first_shock_time = kNone;           // the first frame holding a shock [time]
  double last_smooth_time = kNone;           // the frame before it, if at t > 0 [time]
  double shock_formation_time = kNone;       // t* from the smooth frames' slopes [time]
  std::size_t formation_frames = 0;          // frames in that fit [1]
  std::optional<PowerLawFit> amplitude_fit;  // amplitude ~ t^a, when 3 or more frames are in the window
  double lobe_area_change = kNone;           // max over frames of |A(t) / A(first frame) - 1|, both lobes [1]
};

// frames: one solver's fields at increasing times (at least one frame, the same
// grid in all). fit_window > 1. Throws InputError otherwise.
FieldEvolution analyse_field_evolution(const std::vector<continuum::ContinuumResult>& frames,
                                       double fit_window, double fit_t_min = 0,
                                       const ShockDetectionParams& shocks = {});

}  // namespace shockgas::compare
