// Stage 3: shocks are clusters. The particle state and the continuum field at
// the same time are compared (compare/snapshot_comparison.hpp).
#include <algorithm>
#include <cmath>
#include <string>

#include "run_state.hpp"
#include "shockgas/compare/snapshot_comparison.hpp"
#include "shockgas/compare/theory.hpp"
#include "shockgas/continuum/solve.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::app {

namespace {

using nlohmann::ordered_json;

// t: the time of the compared states.
compare::SnapshotParams snapshot_params(const Scene& scene, double t) {
  const double spacing = domain_length(scene.initial) / static_cast<double>(scene.initial.N);
  return compare::snapshot_params(scene.compare, scene.particles.r, scene.particles.delta, spacing, t);
}

const continuum::ContinuumResult& compared_field(const RunState& state) {
  for (const auto& r : state.continuum)
    if (r.solver == state.scene.compare.solver) return r;
  throw RunError("compare: solver " + state.scene.compare.solver + " did not run");
}

template <class T, class F>
std::vector<double> column(const std::vector<T>& items, F&& f) {
  std::vector<double> out;
  out.reserve(items.size());
  for (const auto& item : items) out.push_back(f(item));
  return out;
}

void write_snapshot(Hdf5File& h5, const compare::SnapshotComparison& c) {
  const auto& g = c.particle_fields;
  h5.set_attribute("/compare", "min_mass", c.min_mass);
  h5.set_attribute("/compare", "t", c.t);
  h5.write("/compare/x", g.x, "length", "cell centres (the continuum grid)");
  h5.write("/compare/rho_particles", g.rho, "mass/length", "particle mass deposited on the grid");
  h5.write("/compare/v_particles", g.v, "length/time", "particle momentum / mass on the grid");
  h5.write("/compare/clusters_x", column(c.clusters, [](auto& k) { return k.x; }), "length", "cluster positions");
  h5.write("/compare/clusters_m", column(c.clusters, [](auto& k) { return k.m; }), "mass", "cluster masses");
  h5.write("/compare/clusters_v", column(c.clusters, [](auto& k) { return k.v; }), "length/time",
           "cluster velocities");
  h5.write("/compare/shocks_x", column(c.shocks, [](auto& s) { return s.x; }), "length", "shock positions");
  h5.write("/compare/shocks_mass", column(c.shocks, [](auto& s) { return s.mass; }), "mass", "shock masses");
  h5.write("/compare/shocks_jump", column(c.shocks, [](auto& s) { return s.jump; }), "length/time",
           "shock velocity jumps v_R - v_L");
  h5.write("/compare/matched_position_error", column(c.match.pairs, [](auto& p) { return p.position_error; }),
           "length", "x_cluster - x_shock of each matched pair");
  h5.write("/compare/sawtooth_slope_times_t", column(c.sawtooth.ramps, [](auto& r) { return r.slope_times_t; }),
           "1", "slope of v on each ramp between shocks, times t (theory: 1)");
}

void summarize_snapshot(RunState& state, const compare::SnapshotComparison& c) {
  auto& s = state.summary["compare"];
  s["solver"] = state.scene.compare.solver;
  s["t"] = c.t;
  s["n_shocks"] = c.n_shocks;
  s["n_clusters"] = c.n_clusters;
  s["matched_mass_fraction"] = c.match.matched_mass_fraction;
  s["matched_pairs"] = c.match.pairs.size();
  s["max_position_error"] = c.match.max_position_error;
  s["rms_velocity_error"] = c.match.rms_velocity_error;
  s["max_relative_mass_error"] = c.match.max_relative_mass_error;
  s["sawtooth_slope_times_t"] = c.sawtooth.slope_times_t.median;
  s["sawtooth_slope_times_t_quartiles"] = {c.sawtooth.slope_times_t.q25, c.sawtooth.slope_times_t.q75};
  s["particle_sawtooth_slope_times_t"] = c.particle_sawtooth.slope_times_t.median;
  s["shock_count_ratio"] = c.shock_count_ratio;
  s["min_mass"] = c.min_mass;
  auto& rep = state.report;
  rep.push_back("## Shocks and clusters at t = " + brief(c.t) + " (solver `" + state.scene.compare.solver + "`)\n");
  rep.push_back("| figure of merit | value | theory / ideal |\n|---|---|---|");
  rep.push_back("| shocks (mass >= " + brief(c.min_mass) + ") | " + std::to_string(c.n_shocks) + " | N t^(-2/3) = " +
                brief(std::round(compare::expected_shock_count(static_cast<double>(state.scene.initial.N), c.t))) + " (ratio " +
                brief(c.shock_count_ratio) + ") |");
  rep.push_back("| clusters (mass >= " + brief(c.min_mass) + ") | " + std::to_string(c.n_clusters) +
                " | = shocks |");
  rep.push_back("| matched cluster mass fraction | " + brief(c.match.matched_mass_fraction) + " | 1 |");
  rep.push_back("| largest matched position error | " + brief(c.match.max_position_error) + " | 0 |");
  rep.push_back("| median sawtooth slope x t (continuum) | " + brief(c.sawtooth.slope_times_t.median) + " | 1 |");
  rep.push_back("| median sawtooth slope x t (particles) | " + brief(c.particle_sawtooth.slope_times_t.median) +
                " | 1 |\n");
}

}  // namespace

// Both models at one time: if the particles stopped before t_end (a collapse, a
// limit), the compared solver is run again to the time they reached.
continuum::ContinuumResult field_at_particle_time(RunState& state) {
  const auto& field = compared_field(state);
  if (state.final_time >= field.t) return field;
  state.report.push_back("- The particles stopped at t = " + brief(state.final_time) + " < t_end: `" + field.solver +
                         "` is compared at that time.\n");
  state.summary["compare"]["note"] = "particles stopped early; continuum re-run to their final time";
  const InitialField initial = make_initial_field(state.scene.initial, 0);
  return continuum::solve(field.solver, initial, state.scene.continuum, state.final_time);
}

void run_compare_stage(RunState& state) {
  if (!state.final_bodies) throw RunError("compare: the particles did not run");
  const auto field = field_at_particle_time(state);
  const auto c = compare::compare_snapshot(*state.final_bodies, state.scene.initial.N, field, snapshot_params(state.scene, field.t));
  write_snapshot(state.h5, c);
  summarize_snapshot(state, c);
}

}  // namespace shockgas::app
