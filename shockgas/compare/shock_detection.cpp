#include "shockgas/compare/shock_detection.hpp"

#include <algorithm>
#include <cmath>

#include "shockgas/core/error.hpp"

namespace shockgas::compare {

namespace {

using Index = long long;  // unrolled (possibly > n) cell and interface indices

// Fraction of the velocity range used as min_jump when it is 0 (automatic).
constexpr double kAutoJumpFraction = 0.05;

struct Grid {
  const std::vector<double>& v;
  const std::vector<double>& rho;
  double length, dx;
  Index n;
  double v_at(Index i) const { return v[static_cast<std::size_t>(((i % n) + n) % n)]; }
  double rho_at(Index i) const {
    return rho.empty() ? 0.0 : rho[static_cast<std::size_t>(((i % n) + n) % n)];
  }
  double centre(Index i) const { return (static_cast<double>(i) + 0.5) * dx; }
  double drop(Index interface) const { return v_at(interface + 1) - v_at(interface); }
};

// A run of compressive interfaces first, ..., first + count - 1 (interface i
// lies between cells i and i + 1).
struct Run {
  Index first;
  Index count;
};

std::vector<Run> compressive_runs(const Grid& g) {
  std::vector<Run> runs;
  Index start = -1;
  for (Index i = 0; i < g.n; ++i)
    if (g.drop(i) >= 0) {
      start = i;
      break;
    }
  if (start < 0) return runs;  // cannot happen on a ring (the drops sum to 0) unless v is NaN
  for (Index k = start + 1; k <= start + g.n; ++k) {
    if (g.drop(k) < 0) {
      if (runs.empty() || runs.back().first + runs.back().count != k) runs.push_back(Run{k, 0});
      ++runs.back().count;
    }
  }
  return runs;
}

// The window of at most max_width interfaces of the run with the largest total drop.
Run steepest_window(const Grid& g, Run run, Index max_width) {
  if (run.count <= max_width) return run;
  Run best{run.first, max_width};
  double sum = 0;
  for (Index k = 0; k < max_width; ++k) sum += g.drop(run.first + k);
  double best_sum = sum;
  for (Index s = 1; s + max_width <= run.count; ++s) {
    sum += g.drop(run.first + s + max_width - 1) - g.drop(run.first + s - 1);
    if (sum < best_sum) {
      best_sum = sum;
      best.first = run.first + s;
    }
  }
  return best;
}

double wrap(double x, double length) {
  double y = std::fmod(x, length);
  if (y < 0) y += length;
  return y >= length ? 0.0 : y;
}

// Shock of the compression region `run` (step 3 and 4 of the header); jump >= 0 if none.
continuum::Shock shock_of_region(const Grid& g, Run run) {
  const Index c0 = run.first, c1 = run.first + run.count;  // cells of the region
  const Index a = c0 - 1, b = c1 + 1;                      // ramp cells either side
  const double slope_left = std::max(0.0, (g.v_at(a) - g.v_at(a - 1)) / g.dx);
  const double slope_right = std::max(0.0, (g.v_at(b + 1) - g.v_at(b)) / g.dx);
  const double s = 0.5 * (slope_left + slope_right);
  const double xa = g.centre(a), xb = g.centre(b);
  const double jump = g.v_at(b) - g.v_at(a) - s * (xb - xa);
  continuum::Shock shock;
  shock.jump = jump;
  if (!(jump < 0)) return shock;
  const double x_left = static_cast<double>(c0) * g.dx, x_right = static_cast<double>(c1 + 1) * g.dx;
  const double width = x_right - x_left;
  const double right_ramp_integral = width * (g.v_at(b) + s * (0.5 * (x_left + x_right) - xb));
  double data_integral = 0, excess_mass = 0;
  const double rho_background = 0.5 * (g.rho_at(a) + g.rho_at(b));
  for (Index i = c0; i <= c1; ++i) {
    data_integral += g.dx * g.v_at(i);
    excess_mass += g.dx * (g.rho_at(i) - rho_background);
  }
  const double xs = std::clamp(x_left + (right_ramp_integral - data_integral) / jump, x_left, x_right);
  const double v_left = g.v_at(a) + s * (xs - xa), v_right = g.v_at(b) + s * (xs - xb);
  shock.x = wrap(xs, g.length);
  shock.mass = std::max(0.0, excess_mass);
  shock.v = 0.5 * (v_left + v_right);
  return shock;
}

double automatic_min_jump(const std::vector<double>& v) {
  const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
  return kAutoJumpFraction * (*hi - *lo);
}

}  // namespace

std::vector<continuum::Shock> detect_shocks(const std::vector<double>& v, const std::vector<double>& rho,
                                            double length, const ShockDetectionParams& params) {
  require(std::isfinite(length) && length > 0, "compare.length", length, "> 0");
  require(v.size() >= 5, "compare.cells", v.size(), ">= 5 cells");
  require(rho.empty() || rho.size() == v.size(), "compare.rho", rho.size(), "empty or one value per cell");
  require(std::isfinite(params.min_jump) && params.min_jump >= 0, "compare.min_jump", params.min_jump,
          ">= 0 (0 = automatic)");
  require(params.max_width_cells >= 1, "compare.max_width_cells", params.max_width_cells, ">= 1");
  for (double vi : v) require(std::isfinite(vi), "compare.v", vi, "finite velocities");
  for (double r : rho) require(std::isfinite(r), "compare.rho", r, "finite densities");

  const Grid g{v, rho, length, length / static_cast<double>(v.size()), static_cast<Index>(v.size())};
  const double min_jump = params.min_jump > 0 ? params.min_jump : automatic_min_jump(v);
  std::vector<continuum::Shock> shocks;
  for (const Run& run : compressive_runs(g)) {
    const double own_drop = g.v_at(run.first + run.count) - g.v_at(run.first);  // the whole run's
    if (own_drop > -0.5 * min_jump) continue;  // a kink, not a compression (header, step 4)
    const continuum::Shock s =
        shock_of_region(g, steepest_window(g, run, static_cast<Index>(params.max_width_cells)));
    if (s.jump < 0 && -s.jump >= min_jump) shocks.push_back(s);
  }
  std::sort(shocks.begin(), shocks.end(), [](const auto& p, const auto& q) { return p.x < q.x; });
  return shocks;
}

std::vector<continuum::Shock> find_shocks(const continuum::ContinuumResult& field,
                                          const ShockDetectionParams& params) {
  if (field.has_shocks) return field.shocks;
  return detect_shocks(field.v, field.rho, field.length, params);
}

}  // namespace shockgas::compare
