#include "shockgas/compare/eulerian_velocity_law.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "shockgas/compare/chernoff.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::compare {

namespace {

double checked_scale(double D) {
  require_above("compare.white_noise_intensity", D, 0.0);
  return std::cbrt(4.0 * D);
}

// v at the centre of cell [s, e) from its average: the field is a ramp of
// slope 1/t (whose average is its centre value) plus the jumps J of the shocks
// inside, each weighting the average by the part of the cell past it:
//     avg = v(centre) + sum_{x_s > centre} J (e - x_s)/dx - sum_{x_s < centre} J (x_s - s)/dx.
double centre_value(const continuum::ContinuumResult& field, std::size_t i, double dx) {
  const double s = static_cast<double>(i) * dx, e = s + dx, centre = s + 0.5 * dx;
  auto shock = std::lower_bound(field.shocks.begin(), field.shocks.end(), s,
                                [](const continuum::Shock& a, double x) { return a.x < x; });
  double v = field.v[i];
  for (; shock != field.shocks.end() && shock->x < e; ++shock)
    v -= shock->x > centre ? shock->jump * (e - shock->x) / dx : -shock->jump * (shock->x - s) / dx;
  return v;
}

}  // namespace

double white_noise_intensity(double velocity_variance, double spacing) {
  require(velocity_variance >= 0 && std::isfinite(velocity_variance), "compare.velocity_variance",
          velocity_variance, "finite and >= 0");
  require_above("compare.spacing", spacing, 0.0);
  return velocity_variance * spacing;
}

double white_noise_intensity(const InitialParams& p) {
  require(p.positions == Positions::lattice, "initial.positions", name_of(p.positions),
          "\"" + name_of(Positions::lattice) + "\" (the white-noise intensity is derived for a lattice)");
  require(p.velocities == Velocities::uniform || p.velocities == Velocities::gaussian, "initial.velocities",
          name_of(p.velocities),
          choices_text({name_of(Velocities::uniform), name_of(Velocities::gaussian)}) +
              " (i.i.d. velocities: white noise)");
  const double variance =
      p.velocities == Velocities::uniform ? p.amplitude * p.amplitude / 3.0 : p.amplitude * p.amplitude;
  return white_noise_intensity(variance, domain_length(p) / static_cast<double>(p.N));
}

double eulerian_velocity_scale(double D) { return checked_scale(D); }

double eulerian_velocity_density(double z, double D) {
  const double s = checked_scale(D);
  return chernoff_density(z / s) / s;
}

double eulerian_velocity_cdf(double z, double D) { return chernoff_cdf(z / checked_scale(D)); }

double eulerian_velocity_quantile(double p, double D) { return checked_scale(D) * chernoff_quantile(p); }

std::vector<double> scaled_law_on_bins(std::span<const double> z_edges, double s,
                                       const std::function<double(double, double)>& integral) {
  require(z_edges.size() >= 2, "compare.histogram_edges", z_edges.size(), ">= 2 edges");
  std::vector<double> mean(z_edges.size() - 1);
  for (std::size_t j = 0; j < mean.size(); ++j) {
    const double width = z_edges[j + 1] - z_edges[j];
    require(width > 0, "compare.histogram_edges", z_edges[j + 1], "increasing");
    mean[j] = integral(z_edges[j] / s, z_edges[j + 1] / s) / width;
  }
  return mean;
}

std::vector<double> eulerian_law_on_bins(std::span<const double> z_edges, double D) {
  return scaled_law_on_bins(z_edges, checked_scale(D), chernoff_integral);
}

DensityCurve eulerian_law_curve(double D, double z_max, std::size_t points) {
  require_above("compare.z_max", z_max, 0.0);
  require(points >= 2, "compare.points", points, ">= 2");
  DensityCurve curve;
  for (std::size_t k = 0; k < points; ++k) {
    const double z = -z_max + 2.0 * z_max * static_cast<double>(k) / static_cast<double>(points - 1);
    curve.z.push_back(z);
    curve.density.push_back(eulerian_velocity_density(z, D));
  }
  return curve;
}

std::vector<double> eulerian_scaled_samples(const continuum::ContinuumResult& field, std::size_t stride) {
  require(field.has_shocks, "compare.field", field.solver, "a field that knows its shocks (hopf_lax)");
  require_above("compare.t", field.t, 0.0);
  require(stride >= 1, "compare.stride", stride, ">= 1");
  const std::size_t cells = field.v.size();
  require(cells >= 1, "compare.field_cells", cells, ">= 1");
  const double dx = field.length / static_cast<double>(cells);
  const double mean = std::accumulate(field.v.begin(), field.v.end(), 0.0) / static_cast<double>(cells);
  const double scale = std::cbrt(field.t);
  std::vector<double> z;
  for (std::size_t i = 0; i < cells; i += stride) z.push_back((centre_value(field, i, dx) - mean) * scale);
  return z;
}

}  // namespace shockgas::compare
