#include "shockgas/compare/deposit.hpp"

#include <cmath>

#include "shockgas/continuum/field.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::compare {

namespace {

double wrap(double x, double length) {
  double y = std::fmod(x, length);
  if (y < 0) y += length;
  return y >= length ? 0.0 : y;
}

void add(GridFields& g, std::size_t cell, double m, double v) {
  g.mass[cell] += m;
  g.momentum[cell] += m * v;
}

void deposit_nearest(GridFields& g, const Bodies& b, double dx) {
  const std::size_t n = g.x.size();
  for (std::size_t i = 0; i < b.size(); ++i) {
    std::size_t c = static_cast<std::size_t>(wrap(b.x[i], g.length) / dx);
    if (c >= n) c = n - 1;
    add(g, c, b.m[i], b.v[i]);
  }
}

void deposit_cloud_in_cell(GridFields& g, const Bodies& b, double dx) {
  const std::size_t n = g.x.size();
  for (std::size_t i = 0; i < b.size(); ++i) {
    // Offset in cells from the centre of cell 0; the left centre is floor of it.
    const double s = wrap(b.x[i], g.length) / dx - 0.5;
    const double left = std::floor(s);
    const double f = s - left;
    const std::size_t c0 = static_cast<std::size_t>(
        (static_cast<long long>(left) + static_cast<long long>(n)) % static_cast<long long>(n));
    add(g, c0, (1 - f) * b.m[i], b.v[i]);
    add(g, (c0 + 1) % n, f * b.m[i], b.v[i]);
  }
}

}  // namespace

GridFields deposit_on_grid(const Bodies& b, double length, std::size_t cells, DepositScheme scheme) {
  require(std::isfinite(length) && length > 0, "compare.length", length, "> 0");
  require(cells >= 1, "compare.cells", cells, ">= 1");
  require(b.v.size() == b.size() && b.m.size() == b.size(), "compare.bodies", b.size(),
          "x, v and m of equal length");
  require_finite_bodies(b, "compare.bodies");  // a NaN would spread over cells, a negative mass empty them
  GridFields g;
  g.length = length;
  g.x = continuum::cell_centres(length, cells);
  g.rho.assign(cells, 0.0);
  g.v.assign(cells, 0.0);
  g.mass.assign(cells, 0.0);
  g.momentum.assign(cells, 0.0);
  const double dx = length / static_cast<double>(cells);
  if (scheme == DepositScheme::nearest_cell)
    deposit_nearest(g, b, dx);
  else
    deposit_cloud_in_cell(g, b, dx);
  for (std::size_t c = 0; c < cells; ++c) {
    g.rho[c] = g.mass[c] / dx;
    if (g.mass[c] > 0) g.v[c] = g.momentum[c] / g.mass[c];
  }
  continuum::fill_empty_cells(g.v, g.mass);  // empty cells: periodic linear interpolation
  return g;
}

}  // namespace shockgas::compare
