#include "shockgas/compare/velocity_distribution.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "shockgas/compare/statistics.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::compare {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

void require_edges(std::span<const double> edges, std::span<const double> counts) {
  require(edges.size() >= 2, "compare.histogram_edges", edges.size(), ">= 2 edges");
  require(counts.size() + 1 == edges.size(), "compare.histogram_counts", counts.size(),
          "one fewer than the edges (" + std::to_string(edges.size()) + ")");
  for (std::size_t j = 1; j < edges.size(); ++j)
    require(edges[j] > edges[j - 1], "compare.histogram_edges", edges[j], "increasing");
}

ScaledDistribution densities(std::vector<double> z_edges, std::span<const double> counts, double total,
                             double t) {
  require(total > 0, "compare.histogram_counts", total, "a total weight > 0");
  ScaledDistribution d{t, std::move(z_edges), std::vector<double>(counts.size())};
  for (std::size_t j = 0; j < counts.size(); ++j) {
    require(counts[j] >= 0, "compare.histogram_counts", counts[j], ">= 0");
    d.density[j] = counts[j] / (total * (d.z_edges[j + 1] - d.z_edges[j]));
  }
  return d;
}

// Density of d at z (piecewise constant; the last edge belongs to the last bin).
double density_at(const ScaledDistribution& d, double z) {
  auto it = std::upper_bound(d.z_edges.begin(), d.z_edges.end(), z);
  if (it == d.z_edges.begin()) return 0.0;
  std::size_t j = static_cast<std::size_t>(it - d.z_edges.begin()) - 1;
  if (j >= d.density.size()) {
    if (z > d.z_edges.back()) return 0.0;
    j = d.density.size() - 1;
  }
  return d.density[j];
}

struct TailPoints {
  std::vector<double> abs_z, log_phi;
};

// Least-squares fit of log_phi = ln Phi0 - c |z|^a for fixed a, and its RSS.
LineFit fit_for_exponent(const TailPoints& p, double a, double* rss) {
  std::vector<double> x(p.abs_z.size());
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = std::pow(p.abs_z[i], a);
  const LineFit line = fit_line(x, p.log_phi);
  *rss = line.rms_residual * line.rms_residual * static_cast<double>(x.size());
  return line;
}

double rss_at(const TailPoints& p, double a) {
  double rss = 0;
  fit_for_exponent(p, a, &rss);
  return rss;
}

// argmin of RSS(a) on [lo, hi]: a 64-point scan, then golden section around the best.
double minimise_rss(const TailPoints& p, double lo, double hi) {
  constexpr int kScan = 64;
  const double step = (hi - lo) / kScan;
  int best = 0;
  double best_rss = std::numeric_limits<double>::infinity();
  for (int k = 0; k <= kScan; ++k) {
    const double r = rss_at(p, lo + k * step);
    if (r < best_rss) {
      best_rss = r;
      best = k;
    }
  }
  double a = std::max(lo, lo + (best - 1) * step), b = std::min(hi, lo + (best + 1) * step);
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  double c = b - g * (b - a), d = a + g * (b - a);
  double fc = rss_at(p, c), fd = rss_at(p, d);
  while (b - a > 1e-12 * std::max(1.0, std::abs(a))) {
    if (fc <= fd) {
      b = d, d = c, fd = fc;
      c = b - g * (b - a), fc = rss_at(p, c);
    } else {
      a = c, c = d, fc = fd;
      d = a + g * (b - a), fd = rss_at(p, d);
    }
  }
  return 0.5 * (a + b);
}

}  // namespace

ScaledDistribution scaled_histogram(std::span<const double> v, std::span<const double> w, double t,
                                    double z_max, std::size_t bins) {
  require(std::isfinite(t) && t > 0, "compare.t", t, "> 0");
  require(std::isfinite(z_max) && z_max > 0, "compare.histogram_zmax", z_max, "> 0");
  require(bins >= 1, "compare.histogram_bins", bins, ">= 1");
  require(w.empty() || w.size() == v.size(), "compare.weights", w.size(), "empty or one per velocity");
  std::vector<double> edges(bins + 1), counts(bins, 0.0);
  const double width = 2 * z_max / static_cast<double>(bins);
  for (std::size_t j = 0; j <= bins; ++j) edges[j] = -z_max + static_cast<double>(j) * width;
  edges[bins] = z_max;
  const double scale = std::cbrt(t);
  double total = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const double wi = w.empty() ? 1.0 : w[i];
    require(wi >= 0, "compare.weights", wi, ">= 0");
    total += wi;
    const double z = v[i] * scale;
    if (!(z >= -z_max && z <= z_max)) continue;
    const std::size_t j = std::min(bins - 1, static_cast<std::size_t>((z + z_max) / width));
    counts[j] += wi;
  }
  return densities(std::move(edges), counts, total, t);
}

ScaledDistribution normalise_z_histogram(std::span<const double> z_edges, std::span<const double> counts,
                                         double t) {
  require_edges(z_edges, counts);
  double total = 0;
  for (double c : counts) total += c;
  return densities(std::vector<double>(z_edges.begin(), z_edges.end()), counts, total, t);
}

ScaledDistribution rescale_v_histogram(std::span<const double> v_edges, std::span<const double> counts,
                                       double t) {
  require(std::isfinite(t) && t > 0, "compare.t", t, "> 0");
  std::vector<double> z_edges(v_edges.begin(), v_edges.end());
  for (double& z : z_edges) z *= std::cbrt(t);
  return normalise_z_histogram(z_edges, counts, t);
}

ScaledDistribution mean_distribution(const std::vector<ScaledDistribution>& d) {
  require(!d.empty(), "compare.distributions", d.size(), ">= 1 distribution");
  ScaledDistribution mean = d.front();
  for (std::size_t k = 1; k < d.size(); ++k) {
    require(d[k].z_edges == mean.z_edges && d[k].density.size() == mean.density.size(),
            "compare.distributions", k, "the same z edges in every distribution");
    for (std::size_t j = 0; j < mean.density.size(); ++j) mean.density[j] += d[k].density[j];
    mean.t = d[k].t;
  }
  for (double& p : mean.density) p /= static_cast<double>(d.size());
  return mean;
}

double standard_deviation(const ScaledDistribution& d) {
  double w = 0, m1 = 0, m2 = 0;
  for (std::size_t b = 0; b + 1 < d.z_edges.size(); ++b) {
    const double z = 0.5 * (d.z_edges[b] + d.z_edges[b + 1]),
                 p = d.density[b] * (d.z_edges[b + 1] - d.z_edges[b]);
    w += p;
    m1 += p * z;
    m2 += p * z * z;
  }
  return w > 0 ? std::sqrt(std::max(0.0, m2 / w - (m1 / w) * (m1 / w))) : 0.0;
}

double collapse_distance(const std::vector<ScaledDistribution>& d, std::size_t grid_points) {
  require(d.size() >= 2, "compare.distributions", d.size(), ">= 2 distributions");
  require(grid_points >= 1, "compare.collapse_grid_points", grid_points, ">= 1");
  double lo = -std::numeric_limits<double>::infinity(), hi = std::numeric_limits<double>::infinity();
  for (const auto& di : d) {
    require(di.z_edges.size() == di.density.size() + 1 && di.z_edges.size() >= 2, "compare.distributions",
            di.z_edges.size(), "edges = bins + 1 >= 2");
    lo = std::max(lo, di.z_edges.front());
    hi = std::min(hi, di.z_edges.back());
  }
  require(hi > lo, "compare.distributions", hi - lo, "overlapping z ranges");
  const double dz = (hi - lo) / static_cast<double>(grid_points);
  double sum = 0;
  std::size_t pairs = 0;
  for (std::size_t a = 0; a < d.size(); ++a)
    for (std::size_t b = a + 1; b < d.size(); ++b, ++pairs)
      for (std::size_t k = 0; k < grid_points; ++k) {
        const double z = lo + (static_cast<double>(k) + 0.5) * dz;
        sum += std::abs(density_at(d[a], z) - density_at(d[b], z)) * dz;
      }
  return sum / static_cast<double>(pairs);
}

TailFit fit_tail_exponent(std::span<const double> z, std::span<const double> phi, double z_min, double a_min,
                          double a_max) {
  require(z.size() == phi.size(), "compare.tail.phi", phi.size(), "one value per z");
  require(std::isfinite(z_min) && z_min >= 0, "compare.tail_zmin", z_min, ">= 0");
  require(a_min > 0 && a_max > a_min, "compare.tail_exponent_range", a_max, "0 < a_min < a_max");
  TailPoints p;
  for (std::size_t i = 0; i < z.size(); ++i)
    if (std::abs(z[i]) >= z_min && phi[i] > 0 && std::isfinite(phi[i])) {
      p.abs_z.push_back(std::abs(z[i]));
      p.log_phi.push_back(std::log(phi[i]));
    }
  require(p.abs_z.size() >= 3, "compare.tail_zmin", z_min, "a tail holding at least 3 points with Phi > 0");
  TailFit fit;
  fit.points = p.abs_z.size();
  fit.exponent = minimise_rss(p, a_min, a_max);
  double rss = 0;
  const LineFit line = fit_for_exponent(p, fit.exponent, &rss);
  fit.c = -line.slope;
  fit.phi0 = std::exp(line.intercept);
  fit.rms_residual = std::sqrt(rss / static_cast<double>(fit.points));
  fit.exponent_error = kNaN;
  const double resolution = 1e-6 * (a_max - a_min);
  fit.at_bound = fit.exponent - a_min < resolution || a_max - fit.exponent < resolution;
  if (!fit.at_bound && fit.points > 3 && rss > 0) {
    const double h = 1e-3 * std::max(1.0, fit.exponent);
    const double curvature = (rss_at(p, fit.exponent + h) - 2 * rss + rss_at(p, fit.exponent - h)) / (h * h);
    const double sigma2 = rss / static_cast<double>(fit.points - 3);
    if (curvature > 0) fit.exponent_error = std::sqrt(2 * sigma2 / curvature);
  }
  return fit;
}

TailFit fit_tail_exponent(const ScaledDistribution& d, double z_min, double a_min, double a_max) {
  std::vector<double> centres(d.density.size());
  for (std::size_t j = 0; j < centres.size(); ++j) centres[j] = 0.5 * (d.z_edges[j] + d.z_edges[j + 1]);
  return fit_tail_exponent(centres, d.density, z_min, a_min, a_max);
}

}  // namespace shockgas::compare
