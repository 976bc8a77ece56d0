#pragma once
// Particles -> fields: mass and momentum of point masses deposited on a uniform
// periodic grid, the same grid of cells [i dx, (i+1) dx) as the continuum run
// (continuum::cell_centres), so the two views compare cell by cell.
//
//   nearest_cell:   body i adds m_i (and m_i v_i) to the cell that contains x_i.
//   cloud_in_cell:  body i adds the fractions (1 - f) and f of m_i to the two
//                   cells whose centres bracket x_i, f = (x_i - x_c) / dx the
//                   offset from the left centre (Hockney & Eastwood 1988, §5-2);
//                   periodic across x = 0.
//
// rho = mass / dx; v = momentum / mass in cells with mass. An empty cell has no
// velocity of its own: it takes the velocity interpolated linearly (periodically)
// between the nearest occupied cells on either side, the same rule as
// continuum::cell_averages, and `mass` = 0 tells callers to mask it (e.g. as
// weights of the sawtooth fit). With no mass anywhere, v = 0.
#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "shockgas/core/bodies.hpp"
#include "shockgas/core/enum_names.hpp"

namespace shockgas::compare {

enum class DepositScheme { nearest_cell, cloud_in_cell };
// "ngp" (nearest grid point), also spelt "nearest"; "cic" (cloud in cell).
constexpr std::array<EnumName<DepositScheme>, 3> enum_names(DepositScheme) {
  return {{{DepositScheme::nearest_cell, "ngp"},
           {DepositScheme::nearest_cell, "nearest"},
           {DepositScheme::cloud_in_cell, "cic"}}};
}

// The scheme named `text` (enum_names above); else InputError naming `key`.
inline DepositScheme parse_deposit_scheme(const std::string& text, const std::string& key) {
  return parse_enum<DepositScheme>(text, key);
}

struct GridFields {
  double length = 1;             // domain length [length]
  std::vector<double> x;         // cell centres [length]
  std::vector<double> rho;       // density [mass/length]
  std::vector<double> v;         // velocity, momentum / mass; empty cells interpolated [length/time]
  std::vector<double> mass;      // mass in each cell [mass]; 0 marks an empty cell
  std::vector<double> momentum;  // momentum in each cell [mass length/time]
};

// Deposits b (positions taken modulo length) on `cells` cells of [0, length).
// Throws InputError unless length > 0, cells >= 1, b's arrays agree in size
// and every body has a finite x and v and a finite mass > 0.
GridFields deposit_on_grid(const Bodies& b, double length, std::size_t cells, DepositScheme scheme);

}  // namespace shockgas::compare
