#include "shockgas/compare/sawtooth.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "shockgas/core/error.hpp"

namespace shockgas::compare {

namespace {

struct RampCells {
  std::vector<double> x, v, w;
};

// Cells of the ramp (x_begin, x_end) (unrolled) that are far enough from both ends.
RampCells ramp_cells(const std::vector<double>& v, const std::vector<double>& weights, double dx,
                     double x_begin, double x_end, double margin) {
  const long long n = static_cast<long long>(v.size());
  RampCells out;
  const long long first = static_cast<long long>(std::ceil((x_begin + margin) / dx - 0.5));
  for (long long j = std::max(first, 0LL); j < first + n + 1; ++j) {
    const double xc = (static_cast<double>(j) + 0.5) * dx;
    if (xc > x_end - margin) break;
    if (xc < x_begin + margin) continue;
    const std::size_t i = static_cast<std::size_t>(j % n);
    const double w = weights.empty() ? 1.0 : weights[i];
    if (w <= 0) continue;
    out.x.push_back(xc);
    out.v.push_back(v[i]);
    out.w.push_back(w);
  }
  return out;
}

void require_length(double length) {
  require(std::isfinite(length) && length > 0, "compare.length", length, "> 0");
}

}  // namespace

SawtoothFit fit_sawtooth_between(const std::vector<double>& v, double length, double t,
                                 const std::vector<Extent>& extents, const SawtoothParams& params,
                                 const std::vector<double>& weights) {
  require_length(length);
  require(std::isfinite(t) && t > 0, "compare.t", t, "> 0");
  require(!v.empty(), "compare.cells", v.size(), ">= 1");
  require(weights.empty() || weights.size() == v.size(), "compare.weights", weights.size(),
          "empty or one per cell");
  for (double vi : v) require(std::isfinite(vi), "compare.v", vi, "finite velocities");
  for (double w : weights) require(std::isfinite(w) && w >= 0, "compare.weights", w, "finite, >= 0");
  require(params.min_cells >= 2, "compare.sawtooth.min_cells", params.min_cells, ">= 2");
  for (std::size_t k = 0; k < extents.size(); ++k) {
    require(extents[k].left >= 0 && extents[k].left < length, "compare.extent.left", extents[k].left,
            "in [0, length)");
    require(extents[k].right >= extents[k].left, "compare.extent.right", extents[k].right, ">= left");
    if (k > 0)
      require(extents[k].left >= extents[k - 1].right, "compare.extent.left", extents[k].left,
              "sorted, not overlapping the previous extent");
  }

  const double dx = length / static_cast<double>(v.size());
  const double margin = (static_cast<double>(params.skip_cells) + 0.5) * dx;
  SawtoothFit fit;
  std::vector<double> products;
  for (std::size_t k = 0; k < extents.size(); ++k) {
    const double x_begin = extents[k].right;
    const double x_end = k + 1 < extents.size() ? extents[k + 1].left : extents[0].left + length;
    if (!(x_end > x_begin)) continue;  // a wrapping object reaching the first one
    const RampCells cells = ramp_cells(v, weights, dx, x_begin, x_end, margin);
    if (cells.x.size() < params.min_cells) continue;
    const LineFit line = fit_line(cells.x, cells.v, cells.w);
    fit.ramps.push_back(
        RampFit{k, x_begin, x_end, cells.x.size(), line.slope, line.slope_error, line.slope * t});
    products.push_back(line.slope * t);
  }
  if (products.empty()) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    fit.slope_times_t = Quartiles{nan, nan, nan};
  } else {
    fit.slope_times_t = quartiles(products);
  }
  return fit;
}

SawtoothFit fit_sawtooth_slopes(const std::vector<double>& v, double length, double t,
                                std::vector<double> shock_x, const SawtoothParams& params,
                                const std::vector<double>& weights) {
  require_length(length);  // before shock_x, whose range it sets
  for (double x : shock_x) require(x >= 0 && x < length, "compare.shock_x", x, "in [0, length)");
  std::sort(shock_x.begin(), shock_x.end());
  std::vector<Extent> points;
  for (double x : shock_x) points.push_back(Extent{x, x});
  return fit_sawtooth_between(v, length, t, points, params, weights);
}

}  // namespace shockgas::compare
