// analyse_field_evolution: a wave's amplitude, lobes, slopes and shocks in time
// (field_evolution.hpp).
#include "shockgas/compare/field_evolution.hpp"

#include <algorithm>
#include <cmath>
#include <span>

#include "shockgas/compare/statistics.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::compare {

namespace {

struct FrameFigures {
  double amplitude = 0, range = 0, steepest = 0, positive = 0, negative = 0;
};

FrameFigures measure(const continuum::ContinuumResult& r) {
  const auto& v = r.v;
  const std::size_t n = v.size();
  const double dx = r.length / static_cast<double>(n);
  FrameFigures f;
  const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
  f.range = *hi - *lo;
  f.amplitude = 0.5 * f.range;
  double mean = 0;
  for (double x : v) mean += x;
  mean /= static_cast<double>(n);
  f.steepest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < n; ++i) {
    f.steepest = std::min(f.steepest, (v[(i + 1) % n] - v[i]) / dx);
    f.positive += std::max(v[i] - mean, 0.0) * dx;
    f.negative += std::min(v[i] - mean, 0.0) * dx;
  }
  return f;
}

// The zero of the line through (t, -1/slope) over the resolved smooth frames.
void fit_formation(FieldEvolution& e, const std::vector<FrameFigures>& figures, std::size_t smooth_frames,
                   double dx) {
  std::vector<double> t, y;
  e.formation_fit.assign(e.t.size(), 0.0);
  for (std::size_t k = 0; k < smooth_frames; ++k) {
    const FrameFigures& f = figures[k];
    if (f.steepest < 0 && -f.steepest * dx <= kResolvedStep * f.range) {
      t.push_back(e.t[k]);
      y.push_back(-1.0 / f.steepest);
      e.formation_fit[k] = 1;
    }
  }
  e.formation_frames = t.size();
  if (t.size() < 2) return;
  const LineFit line = fit_line(std::span<const double>(t), std::span<const double>(y));
  if (line.slope < 0) e.shock_formation_time = -line.intercept / line.slope;
}

void fit_amplitude(FieldEvolution& e, double fit_window, double fit_t_min) {
  std::vector<double> t, a;
  const double t_last = e.t.back();
  const double broken = std::isfinite(e.first_shock_time) ? e.first_shock_time : 0.0;
  const double t_from = std::max({t_last / fit_window, fit_t_min, broken});
  for (std::size_t k = 0; k < e.t.size(); ++k)
    if (e.t[k] > 0 && e.amplitude[k] > 0 && e.t[k] >= t_from) {
      t.push_back(e.t[k]);
      a.push_back(e.amplitude[k]);
    }
  if (t.size() >= 3) e.amplitude_fit = fit_power_law(t, a, t.front(), t.back());
}

double relative_change(double a, double a0) { return a0 != 0 ? std::abs(a / a0 - 1) : 0.0; }

}  // namespace

FieldEvolution analyse_field_evolution(const std::vector<continuum::ContinuumResult>& frames,
                                       double fit_window, double fit_t_min,
                                       const ShockDetectionParams& shock_params) {
  require(!frames.empty(), "output.animation_frames", frames.size(), "at least one frame");
  require_above("compare.fit_window", fit_window, 1.0);
  const std::size_t cells = frames.front().v.size();
  FieldEvolution e;
  std::vector<FrameFigures> figures;
  std::size_t smooth_frames = frames.size();
  for (std::size_t k = 0; k < frames.size(); ++k) {
    const auto& r = frames[k];
    require(r.v.size() == cells && cells >= 5, "continuum.cells", r.v.size(),
            "the same grid of >= 5 cells in every frame");
    if (k > 0) require(r.t > frames[k - 1].t, "output.animation_frames", r.t, "frames at increasing times");
    const FrameFigures f = measure(r);
    figures.push_back(f);
    e.t.push_back(r.t);
    e.amplitude.push_back(f.amplitude);
    e.steepest_slope.push_back(f.steepest);
    e.positive_area.push_back(f.positive);
    e.negative_area.push_back(f.negative);
    e.shocks.push_back(static_cast<double>(find_shocks(r, shock_params).size()));
    if (r.t > 0 && e.shocks.back() > 0 && smooth_frames == frames.size()) {
      smooth_frames = k;
      e.first_shock_time = r.t;
      if (k > 0 && frames[k - 1].t > 0) e.last_smooth_time = frames[k - 1].t;
    }
  }
  fit_formation(e, figures, smooth_frames, frames.front().length / static_cast<double>(cells));
  fit_amplitude(e, fit_window, fit_t_min);
  e.lobe_area_change = 0;
  for (std::size_t k = 0; k < frames.size(); ++k)
    e.lobe_area_change =
        std::max({e.lobe_area_change, relative_change(e.positive_area[k], e.positive_area[0]),
                  relative_change(e.negative_area[k], e.negative_area[0])});
  return e;
}

}  // namespace shockgas::compare
