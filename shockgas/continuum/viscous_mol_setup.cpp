#include "shockgas/continuum/viscous_mol_setup.hpp"

#include <algorithm>
#include <cmath>

#include "shockgas/core/error.hpp"

namespace shockgas::continuum {

namespace {

void check_input(const ContinuumParams& p, double t_end) {
  require_above("continuum.nu", p.nu, 0.0);
  require(p.cells >= 8, "continuum.cells", p.cells, "an integer >= 8");
  require_in_range("continuum.rtol", p.rtol, 1e-12, 1e-1);
  require(std::isfinite(t_end) && t_end >= 0, "continuum.t_end", t_end, "a finite time >= 0");
}

// Dv h / nu <= 2 (viscous_mol.hpp): the central advection resolves the shock.
void check_resolution(const ContinuumParams& p, const std::vector<double>& v, double length) {
  const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
  const double dv = *hi - *lo;
  const double h = length / static_cast<double>(p.cells);
  if (p.allow_unstable || dv * h / p.nu <= 2.0) return;
  const double needed = std::ceil(dv * length / (2.0 * p.nu));
  throw InputError("continuum.cells", to_text(p.cells),
                   ">= " + to_text(needed) + " cells for nu = " + to_text(p.nu) +
                       " (the viscous shock width 4 nu / (max v0 - min v0) must span 2 cells; "
                       "set continuum.allow_unstable = true to run anyway)");
}

// nu t_end / h^2 <= kMaxMolStiffness: beyond it the solution has decayed to
// its mean many times over, and the integrators lose it.
void check_stiffness(const ContinuumParams& p, double t_end, double length) {
  const double h = length / static_cast<double>(p.cells);
  const double stiffness = p.nu * t_end / (h * h);
  if (p.allow_unstable || stiffness <= kMaxMolStiffness) return;
  throw InputError("continuum.nu", to_text(p.nu),
                   "nu t_end / h^2 <= " + to_text(kMaxMolStiffness) +
                       " for the method-of-lines solvers (it is " + to_text(stiffness) +
                       ": the integrators are not accurate that stiff; hopf_cole takes large nu; set "
                       "continuum.allow_unstable = true to run anyway)");
}

}  // namespace

void check_mol_input(const InitialField& f, const ContinuumParams& p, double t_end) {
  check_input(p, t_end);
  check_resolution(p, cell_averages(f, p.cells).v, f.length);
  check_stiffness(p, t_end, f.length);
}

SolverInfo mol_registration(const std::string& name) {
  SolverInfo s;
  s.name = name;
  s.density = true;
  s.viscous = true;
  s.preflight = check_mol_input;
  return s;
}

MolProblem make_mol_problem(const InitialField& f, const ContinuumParams& p, double t_end,
                            const std::string& solver) {
  check_input(p, t_end);
  const CellAverages a = cell_averages(f, p.cells);
  check_resolution(p, a.v, f.length);
  check_stiffness(p, t_end, f.length);
  MolProblem m;
  m.solver = solver;
  m.grid = {p.cells, f.length / static_cast<double>(p.cells), p.nu};
  m.y0.resize(2 * p.cells);
  double scale = 0;
  for (std::size_t i = 0; i < p.cells; ++i) {
    m.y0[2 * i] = a.v[i];
    m.y0[2 * i + 1] = a.rho[i];
    scale = std::max({scale, std::abs(a.v[i]), std::abs(a.rho[i])});
  }
  m.rtol = p.rtol;
  m.atol = p.rtol * (scale > 0 ? scale : 1.0);
  const auto [lo, hi] = std::minmax_element(a.v.begin(), a.v.end());
  m.v_min = *lo, m.v_max = *hi;
  m.bounded = !p.allow_unstable;
  m.t_end = t_end;
  m.length = f.length;
  require_finite_state(m, m.y0, 0.0);
  return m;
}

void require_finite_state(const MolProblem& m, std::span<const double> y, double t) {
  const auto where = [&](std::size_t k) {
    const std::size_t cell = k / 2;
    return " in cell " + std::to_string(cell) +
           " (x = " + to_text((static_cast<double>(cell) + 0.5) * m.grid.h) + ") at t = " + to_text(t);
  };
  for (std::size_t k = 0; k < y.size(); ++k)
    if (!std::isfinite(y[k]))
      throw RunError(m.solver + ": non-finite " + (k % 2 == 0 ? "velocity" : "density") + where(k));
  if (!m.bounded) return;
  const double slack = std::max(1e-2, 10 * m.rtol) * (m.v_max - m.v_min);
  for (std::size_t k = 0; k < y.size(); k += 2)
    if (y[k] < m.v_min - slack || y[k] > m.v_max + slack)
      throw RunError(m.solver + ": velocity " + to_text(y[k]) + where(k) + ", outside the initial range [" +
                     to_text(m.v_min) + ", " + to_text(m.v_max) +
                     "] that viscous Burgers keeps (maximum principle): the integration failed");
}

ContinuumResult mol_result(const MolProblem& m, std::span<const double> y) {
  ContinuumResult r;
  r.solver = m.solver;
  r.t = m.t_end;
  r.length = m.length;
  r.x = cell_centres(m.length, m.grid.cells);
  r.v.resize(m.grid.cells);
  r.rho.resize(m.grid.cells);
  for (std::size_t i = 0; i < m.grid.cells; ++i) {
    r.v[i] = y[2 * i];
    r.rho[i] = y[2 * i + 1];
  }
  return r;
}

ContinuumResult mol_initial_result(const MolProblem& m, const std::string& integrator) {
  ContinuumResult r = mol_result(m, m.y0);
  r.method_note = integrator + " at t = 0: the initial cell averages";
  return r;
}

}  // namespace shockgas::continuum
