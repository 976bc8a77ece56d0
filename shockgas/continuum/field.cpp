#include "shockgas/continuum/field.hpp"

#include <array>
#include <cmath>

namespace shockgas::continuum {

std::vector<double> cell_centres(double length, std::size_t cells) {
  std::vector<double> x(cells);
  const double dx = length / static_cast<double>(cells);
  for (std::size_t i = 0; i < cells; ++i) x[i] = (static_cast<double>(i) + 0.5) * dx;
  return x;
}

namespace {

// 6-point Gauss-Legendre nodes and weights on [-1, 1] (exact for degree 11).
constexpr std::array<double, 6> kNodes = {-0.932469514203152, -0.661209386466265, -0.238619186083197,
                                          0.238619186083197,  0.661209386466265,  0.932469514203152};
constexpr std::array<double, 6> kWeights = {0.171324492379170, 0.360761573048139, 0.467913934572691,
                                            0.467913934572691, 0.360761573048139, 0.171324492379170};

CellAverages from_functions(const InitialField& f, std::size_t cells) {
  CellAverages a{std::vector<double>(cells), std::vector<double>(cells)};
  const double dx = f.length / static_cast<double>(cells);
  // Data constant on pieces that hold whole cells: the cell's value itself.
  const bool piecewise = f.pieces > 0 && cells % f.pieces == 0;
  for (std::size_t i = 0; i < cells; ++i) {
    const double mid = (static_cast<double>(i) + 0.5) * dx;
    if (piecewise) {
      a.v[i] = f.v0(mid);
      a.rho[i] = f.rho0 ? f.rho0(mid) : 1.0;
      continue;
    }
    double sv = 0, sr = 0;
    for (std::size_t k = 0; k < kNodes.size(); ++k) {
      const double x = mid + 0.5 * dx * kNodes[k];
      sv += kWeights[k] * f.v0(x);
      sr += kWeights[k] * (f.rho0 ? f.rho0(x) : 1.0);
    }
    a.v[i] = 0.5 * sv;
    a.rho[i] = 0.5 * sr;
  }
  return a;
}

}  // namespace

void fill_empty_cells(std::vector<double>& v, const std::vector<double>& mass) {
  const std::size_t n = v.size();
  std::vector<std::size_t> occupied;
  for (std::size_t i = 0; i < n; ++i)
    if (mass[i] > 0) occupied.push_back(i);
  if (occupied.empty()) return;
  for (std::size_t k = 0; k < occupied.size(); ++k) {
    const std::size_t a = occupied[k], b = occupied[(k + 1) % occupied.size()];
    const std::size_t gap = (b + n - a) % n == 0 ? n : (b + n - a) % n;
    for (std::size_t j = 1; j < gap; ++j) {
      const double w = static_cast<double>(j) / static_cast<double>(gap);
      v[(a + j) % n] = (1 - w) * v[a] + w * v[b];
    }
  }
}

namespace {

CellAverages from_bodies(const InitialField& f, std::size_t cells) {
  CellAverages a{std::vector<double>(cells, 0.0), std::vector<double>(cells, 0.0)};
  const double dx = f.length / static_cast<double>(cells);
  std::vector<double> mass(cells, 0.0), momentum(cells, 0.0);
  const Bodies& b = f.bodies;
  for (std::size_t i = 0; i < b.size(); ++i) {
    double xi = std::fmod(b.x[i], f.length);
    if (xi < 0) xi += f.length;
    std::size_t c = static_cast<std::size_t>(xi / dx);
    if (c >= cells) c = cells - 1;
    mass[c] += b.m[i];
    momentum[c] += b.m[i] * b.v[i];
  }
  for (std::size_t c = 0; c < cells; ++c) {
    a.rho[c] = mass[c] / dx;
    a.v[c] = mass[c] > 0 ? momentum[c] / mass[c] : 0.0;
  }
  fill_empty_cells(a.v, mass);
  return a;
}

}  // namespace

CellAverages cell_averages(const InitialField& f, std::size_t cells) {
  return f.from_bodies() ? from_bodies(f, cells) : from_functions(f, cells);
}

}  // namespace shockgas::continuum
