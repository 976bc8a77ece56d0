// The pressureless gas by first-order Godunov: the physics of
// pressureless_physics.hpp on the generic grid of godunov_scheme.hpp.
#include "shockgas/continuum/pressureless.hpp"

#include "shockgas/continuum/godunov_scheme.hpp"
#include "shockgas/continuum/pressureless_physics.hpp"
#include "shockgas/core/cores.hpp"

namespace shockgas::continuum {

namespace {

using Grid = FiniteVolumeGrid<PressurelessGas>;

// The conserved Godunov CFL bound: a cell's mass leaves through one face at
// most, at a fraction dt |u| / dx <= cfl of it.
constexpr double kPressurelessCflMax = 1.0;

constexpr const char* kName = "pressureless";  // as registered

void check_input(const InitialField& f, const ContinuumParams& p, double t_end) {
  check_finite_volume_input(p, t_end, kPressurelessCflMax, kName);
  check_initial_averages(cell_averages(f, p.cells), f.length);
}

std::vector<PressurelessGas::State> initial_states(const CellAverages& a) {
  std::vector<PressurelessGas::State> u(a.v.size());
  for (std::size_t i = 0; i < u.size(); ++i) u[i] = {a.rho[i], a.rho[i] * a.v[i]};
  return u;
}

}  // namespace

ContinuumResult solve_pressureless(const InitialField& f, const ContinuumParams& p, double t_end,
                                   const ProgressCallback& progress) {
  const std::string solver = kName;
  check_finite_volume_input(p, t_end, kPressurelessCflMax, solver);
  const CellAverages initial = cell_averages(f, p.cells);
  check_initial_averages(initial, f.length);

  Grid grid(initial_states(initial), f.length / static_cast<double>(p.cells), p.boundary,
            resolved_threads(p.threads));
  const std::size_t steps = advance(grid, TimeLoop{t_end, p.cfl, solver, progress},
                                    [&](double dt) { return grid.step_godunov(dt); });

  ContinuumResult r;
  r.solver = solver;
  r.t = t_end;
  r.length = f.length;
  r.x = cell_centres(f.length, grid.size());
  r.v.resize(grid.size());
  r.rho.resize(grid.size());
  for (std::size_t i = 0; i < grid.size(); ++i) {
    r.rho[i] = grid.cell(i)[0];
    r.v[i] = PressurelessGas::velocity(grid.cell(i));
  }
  r.method_note = "first-order Godunov, exact pressureless Riemann flux (delta-shocks, vacuum)";
  r.stats["steps"] = static_cast<double>(steps);
  r.stats["cells"] = static_cast<double>(p.cells);
  r.stats["cfl"] = p.cfl;
  return r;
}

SolverInfo pressureless_solver() {
  SolverInfo s;
  s.name = kName;
  s.summary = "the pressureless gas (sticky particles' continuum), first-order Godunov with delta-shocks";
  s.label = s.name + " (sticky gas, 1st order)";
  s.colour = "tab:green";
  s.bytes_per_cell = 60;  // peak resident memory at work, measured at 2e4-4e5 cells
  s.density = true;
  s.outflow = true;
  s.preflight = check_input;
  s.run = solve_pressureless;
  return s;
}

}  // namespace shockgas::continuum
