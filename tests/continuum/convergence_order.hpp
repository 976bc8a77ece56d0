#pragma once
// The measured order of convergence of errors on a sequence of refined grids,
// shared by the order tests of the finite-volume schemes.
#include <cmath>
#include <cstddef>
#include <vector>

namespace shockgas::continuum {

// Least-squares slope of -log(error) against log(cells) (error ~ C cells^-order):
// one number for all grids, steadier than the rate of any single pair of grids.
inline double convergence_order(const std::vector<std::size_t>& cells, const std::vector<double>& error) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const double n = static_cast<double>(cells.size());
  for (std::size_t k = 0; k < cells.size(); ++k) {
    const double x = std::log(static_cast<double>(cells[k])), y = -std::log(error[k]);
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
  }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

}  // namespace shockgas::continuum
