#include "shockgas/compare/field_distance.hpp"

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

}  // namespace shockgas::compare
