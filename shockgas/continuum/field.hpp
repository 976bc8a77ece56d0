#pragma once
// What every continuum solver returns, and the discretisation of the initial
// data that they share.
#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include "shockgas/core/initial_condition.hpp"

namespace shockgas::continuum {

// A shock of the velocity field: a discontinuity with v_left > v_right. For the
// exact solver the mass is the mass of the Lagrangian interval it has swallowed
// (a delta-shock of the density).
struct Shock {
  double x = 0;     // position [length], in [0, length) on a periodic domain
  double mass = 0;  // mass held in the shock [mass]
  double jump = 0;  // v_right - v_left [length/time], < 0
  double v = 0;     // shock velocity [length/time]
};

// Fields at time t on a uniform grid of cells [i dx, (i+1) dx).
struct ContinuumResult {
  std::string solver;                   // the registered name (registry.hpp)
  double t = 0;                         // time of the fields [time]
  double length = 1;                    // domain length [length]
  std::vector<double> x;                // cell centres [length]
  std::vector<double> v;                // cell averages of the velocity [length/time]
  std::vector<double> rho;              // cell averages of the density [mass/length]
  bool has_shocks = false;              // whether the solver knows its shocks
  std::vector<Shock> shocks;            // sorted by x
  std::string method_note;              // which path ran and why (e.g. Hopf-Cole FFT vs log-domain)
  std::map<std::string, double> stats;  // solver counters: steps, rhs evaluations, ...
  double wall_seconds = 0;              // filled by the caller
};

// Cell centres (i + 1/2) dx of `cells` cells on [0, length).
std::vector<double> cell_centres(double length, std::size_t cells);

// Cell averages of the initial data on `cells` cells of [0, f.length):
//  * pointwise data (f.v0, f.rho0): 6-point Gauss-Legendre in each cell, rho the
//    average density and v the average velocity (Burgers' conserved variable);
//    data constant on f.pieces equal pieces, with cells a multiple of f.pieces:
//    the value at each cell's centre (its exact average);
//  * point masses: nearest-cell deposit, rho = mass / dx, v = momentum / mass;
//    an empty cell takes the velocity interpolated linearly (periodically)
//    between its occupied neighbours.
struct CellAverages {
  std::vector<double> v, rho;
};
CellAverages cell_averages(const InitialField& f, std::size_t cells);

// Gives every cell without mass (mass[i] <= 0) the velocity interpolated
// linearly, periodically, between the occupied cells around it.
void fill_empty_cells(std::vector<double>& v, const std::vector<double>& mass);

}  // namespace shockgas::continuum
