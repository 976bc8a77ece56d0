// Stage 2: the continuum solvers, side by side, each measured against the exact
// Hopf-Lax solution when the scene runs it too.
#include <cmath>
#include <string>

#include "run_state.hpp"
#include "shockgas/continuum/registry.hpp"
#include "shockgas/continuum/solve.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::app {

namespace {

using continuum::ContinuumResult;

void write_result(Hdf5File& h5, const ContinuumResult& r, bool fields) {
  const std::string g = "/continuum/" + r.solver;
  if (fields) {
    h5.write(g + "/x", r.x, "length", "cell centres");
    h5.write(g + "/v", r.v, "length/time", "cell averages of the velocity at t");
    if (!r.rho.empty()) h5.write(g + "/rho", r.rho, "mass/length", "cell averages of the density at t");
  }
  if (r.has_shocks) {
    std::vector<double> x, mass, jump, v;
    for (const auto& s : r.shocks) {
      x.push_back(s.x);
      mass.push_back(s.mass);
      jump.push_back(s.jump);
      v.push_back(s.v);
    }
    h5.write(g + "/shocks/x", x, "length", "shock positions");
    h5.write(g + "/shocks/mass", mass, "mass", "mass held in each shock");
    h5.write(g + "/shocks/jump", jump, "length/time", "velocity jump v_right - v_left (< 0)");
    h5.write(g + "/shocks/v", v, "length/time", "shock velocities");
  }
  const auto& info = continuum::solver_info(r.solver);
  h5.set_attribute(g, "label", info.label);
  h5.set_attribute(g, "colour", info.colour);
  h5.set_attribute(g, "t", r.t);
  h5.set_attribute(g, "method", r.method_note);
  h5.set_attribute(g, "wall_seconds", r.wall_seconds);
}

// L1 distance of cell averages, sum |a - b| dx.
double l1_distance(const std::vector<double>& a, const std::vector<double>& b, double dx) {
  double s = 0;
  for (std::size_t i = 0; i < a.size() && i < b.size(); ++i) s += std::abs(a[i] - b[i]);
  return s * dx;
}

double total(const std::vector<double>& rho, double length) {
  double sum = 0;
  for (double x : rho) sum += x;
  return sum * length / static_cast<double>(rho.size());
}

void summarize(RunState& state, const ContinuumResult& r, const ContinuumResult* exact, double mass0) {
  auto& s = state.summary["continuum"][r.solver];
  s["cells"] = r.x.size();
  s["t"] = r.t;
  s["wall_seconds"] = r.wall_seconds;
  s["method"] = r.method_note;
  for (const auto& [k, v] : r.stats) s["stats"][k] = v;
  if (r.has_shocks) s["n_shocks"] = r.shocks.size();
  if (!r.rho.empty()) s["mass_drift"] = total(r.rho, r.length) / mass0 - 1;  // 0 up to rounding if conserved
  std::string line = "- `" + r.solver + "`: " + std::to_string(r.x.size()) + " cells, " + brief(r.wall_seconds) +
                     " s";
  if (exact && exact != &r && exact->v.size() == r.v.size()) {
    const double dx = r.length / static_cast<double>(r.v.size());
    s["l1_error_v"] = l1_distance(r.v, exact->v, dx);
    line += "; L1 distance to the exact Hopf-Lax solution: v " + brief(s["l1_error_v"].get<double>());
    if (r.rho.size() == exact->rho.size()) {
      s["l1_error_rho"] = l1_distance(r.rho, exact->rho, dx);
      line += ", rho " + brief(s["l1_error_rho"].get<double>());
    }
  }
  if (!r.method_note.empty()) line += " (" + r.method_note + ")";
  state.report.push_back(line);
}

}  // namespace

void run_continuum_stage(RunState& state) {
  const auto& scene = state.scene;
  const double t_end = scene.continuum_t_end();
  const InitialField field = make_initial_field(scene.initial, 0);
  const double mass0 = total(continuum::cell_averages(field, scene.continuum.cells).rho, field.length);
  for (const auto& name : scene.continuum.solvers) {
    state.progress.stage("continuum/" + name);
    state.continuum.push_back(continuum::solve(name, field, scene.continuum, t_end, state.progress.callback()));
    state.progress.finish();
  }
  const ContinuumResult* exact = nullptr;
  for (const auto& r : state.continuum)
    if (continuum::solver_info(r.solver).exact) exact = &r;
  state.report.push_back("## Continuum at t = " + brief(t_end) + "\n");
  for (const auto& r : state.continuum) {
    write_result(state.h5, r, scene.output.fields);
    summarize(state, r, exact, mass0);
  }
  state.report.push_back("");
}

}  // namespace shockgas::app
