// Input rules and failure reports shared by the finite-volume solvers
// (godunov_scheme.hpp): refused before the run with the allowed range, or
// stopped with the solver, the time and the cell.
#include <cmath>

#include "shockgas/continuum/godunov_scheme.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::continuum {

// Fewer cells than this cannot hold the 5-cell MUSCL stencil of a periodic grid
// plus one resolved wave; the same rule as validate(ContinuumParams).
constexpr std::size_t kMinCells = 8;

void check_finite_volume_input(const ContinuumParams& p, double t_end, double cfl_max,
                               const std::string& scheme) {
  require(p.cells >= kMinCells, "continuum.cells", p.cells, "an integer >= 8");
  const bool stable = p.cfl <= cfl_max || p.allow_unstable;
  require(std::isfinite(p.cfl) && p.cfl > 0 && stable, "continuum.cfl", p.cfl,
          "a Courant number in (0, " + to_text(cfl_max) + "] for " + scheme +
              " (set continuum.allow_unstable = true to go beyond)");
  require(std::isfinite(t_end) && t_end >= 0, "continuum.t_end", t_end, "a finite time >= 0");
}

void check_initial_averages(const CellAverages& a, double length) {
  const double dx = length / static_cast<double>(a.v.size());
  auto where = [dx](std::size_t i) {
    return "cell " + std::to_string(i) + " (x = " + to_text((static_cast<double>(i) + 0.5) * dx) + ")";
  };
  for (std::size_t i = 0; i < a.v.size(); ++i) {
    if (!std::isfinite(a.v[i]))
      throw InputError("initial.v0", to_text(a.v[i]) + " in " + where(i), "finite values on the domain");
    if (!(std::isfinite(a.rho[i]) && a.rho[i] >= 0))
      throw InputError("initial.rho0", to_text(a.rho[i]) + " in " + where(i),
                       "finite values >= 0 on the domain");
  }
}

void throw_non_finite(const std::string& solver, double t, std::size_t step, std::size_t cell, double x,
                      const std::string& component, double value) {
  throw RunError(solver + ": non-finite " + component + " = " + to_text(value) + " in cell " +
                 std::to_string(cell) + " (x = " + to_text(x) + ") at t = " + to_text(t) + " (step " +
                 std::to_string(step) + "); no field written");
}

void throw_stalled(const std::string& solver, double t, double dt) {
  throw RunError(solver + ": time step " + to_text(dt) + " no longer advances t = " + to_text(t) +
                 " (the speeds have blown up); no field written");
}

}  // namespace shockgas::continuum
