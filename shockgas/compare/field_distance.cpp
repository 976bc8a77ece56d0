#include "shockgas/compare/field_distance.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "shockgas/core/error.hpp"

namespace shockgas::compare {

// On a uniform grid dx cancels: (1/L) sum |a - b| dx = mean |a - b|, and the
// ratio of two sums over the same cells is the ratio of the integrals.
L1Distance l1_distance(const std::vector<double>& a, const std::vector<double>& reference, L1Scale scale) {
  require(!reference.empty(), "l1_distance.reference", reference.size(), "at least one cell");
  require(a.size() == reference.size(), "l1_distance.field", a.size(),
          "as many cells as the reference (" + std::to_string(reference.size()) + ")");
  const double n = static_cast<double>(a.size());
  const double c =
      scale == L1Scale::about_mean ? std::accumulate(reference.begin(), reference.end(), 0.0) / n : 0.0;
  double distance = 0, size = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    distance += std::abs(a[i] - reference[i]);
    size += std::abs(reference[i] - c);
  }
  return {distance / n, size > 0 ? distance / size : std::numeric_limits<double>::quiet_NaN()};
}

namespace {

// M between the centres of cells i and i + 1: the mass of cells 0..i over the whole.
std::vector<double> cumulative_between_centres(const std::vector<double>& rho) {
  const double mass = std::accumulate(rho.begin(), rho.end(), 0.0);
  require(mass > 0, "mass_distance.rho", mass, "a positive mass");
  std::vector<double> m(rho.size());
  double through = 0;
  for (std::size_t i = 0; i < rho.size(); ++i) {
    through += rho[i];
    m[i] = through / mass;
  }
  return m;
}

}  // namespace

double mass_distance(const std::vector<double>& rho, const std::vector<double>& reference) {
  require(!reference.empty(), "mass_distance.reference", reference.size(), "at least one cell");
  require(rho.size() == reference.size(), "mass_distance.rho", rho.size(),
          "as many cells as the reference (" + std::to_string(reference.size()) + ")");
  const std::vector<double> a = cumulative_between_centres(rho), b = cumulative_between_centres(reference);
  std::vector<double> d(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) d[i] = a[i] - b[i];
  std::vector<double> sorted = d;
  const auto middle = sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2);
  std::nth_element(sorted.begin(), middle, sorted.end());
  const double c = *middle;  // a median: the shift that minimises the sum of |d - c|
  double sum = 0;
  for (double x : d) sum += std::abs(x - c);
  return sum / static_cast<double>(d.size());
}

}  // namespace shockgas::compare
