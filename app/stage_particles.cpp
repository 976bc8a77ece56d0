// Stage 1: the particle gas (an ensemble of event-driven or exact-hull runs).
#include <cmath>
#include <string>

#include "run_state.hpp"
#include "shockgas/core/error.hpp"
#include "shockgas/particles/simulate.hpp"

namespace shockgas::app {

namespace {

using particles::EnsembleResult;

void write_series(Hdf5File& h5, const EnsembleResult& e) {
  h5.write("/particles/t", e.t, "time", "log-spaced sample times");
  h5.write("/particles/count", e.count, "1", "realizations that reached each sample");
  struct Column {
    const char* name;
    const particles::SeriesStats& s;
    const char* unit;
    const char* doc;
  };
  const Column columns[] = {
      {"T", e.T, "length^2/time^2", "temperature <v^2> - <v>^2, mass weighted"},
      {"mean_v", e.mean_v, "length/time", "mass-weighted mean velocity (momentum check)"},
      {"n_bodies", e.n_bodies, "1", "bodies (clusters after merges)"},
      {"n_clusters", e.n_clusters, "1", "clusters by the default cluster criteria"},
      {"collisions", e.collisions, "1", "cumulative collisions, all kinds"},
      {"inelastic", e.inelastic, "1", "cumulative inelastic collisions"},
      {"elastic", e.elastic, "1", "cumulative elastic sub-threshold collisions"},
      {"merges", e.merges, "1", "cumulative merges"},
      {"dissipated", e.dissipated, "mass length^2/time^2", "cumulative kinetic energy dissipated"},
  };
  for (const auto& c : columns) {
    if (c.s.mean.empty()) continue;
    h5.write(std::string("/particles/") + c.name, c.s.mean, c.unit, std::string(c.doc) + " (ensemble mean)");
    h5.write(std::string("/particles/") + c.name + "_stderr", c.s.stderr_, c.unit,
             std::string("standard error of ") + c.name);
  }
}

void write_bodies(Hdf5File& h5, const std::string& group, const Bodies& b, const std::string& what) {
  h5.write(group + "/x", b.x, "length", what + ": positions (ring: in [0, L))");
  h5.write(group + "/v", b.v, "length/time", what + ": velocities");
  h5.write(group + "/m", b.m, "mass", what + ": masses");
}

std::vector<double> bin_centres(const particles::ScaledHistogram& hist) {
  std::vector<double> z(hist.bins);
  for (std::size_t b = 0; b < hist.bins; ++b) z[b] = -hist.zmax + (b + 0.5) * 2 * hist.zmax / hist.bins;
  return z;
}

void write_records(Hdf5File& h5, const EnsembleResult& e, const particles::ParticleParams& p) {
  const auto& first = e.first;
  write_bodies(h5, "/particles/final", first.final_state, "state at t_end (realization 0)");
  for (std::size_t k = 0; k < first.snapshots.size(); ++k) {
    const std::string group = "/particles/snapshots/" + std::to_string(k);
    write_bodies(h5, group, first.snapshots[k].bodies, "snapshot (realization 0)");
    h5.set_attribute(group, "t", first.snapshots[k].t);
  }
  const auto& hist = first.histogram;
  if (hist.bins > 0 && !hist.t.empty()) {
    h5.write("/particles/histogram/z", bin_centres(hist), "length/time^(2/3)",
             "bin centres of z = (v - <v>) t^(1/3)");
    h5.write("/particles/histogram/t", hist.t, "time", "sample times");
    h5.write_matrix("/particles/histogram/density", e.histogram, hist.t.size(), hist.bins,
                    "time^(2/3)/length", "mass-weighted density of z, ensemble mean (rows: times)");
  }
  const auto& st = first.spacetime;
  if (p.spacetime && !st.t.empty()) {
    h5.write("/particles/spacetime/t", st.t, "time", "frame times");
    h5.write_matrix("/particles/spacetime/x", st.x, st.t.size(), st.n, "length",
                    "position of every original particle at each frame (realization 0)");
  }
}

void summarize(RunState& state, const EnsembleResult& e) {
  const auto& p = state.scene.particles;
  auto& s = state.summary["particles"];
  s["solver"] = p.solver;
  s["r"] = p.r;
  s["delta"] = p.delta;
  s["realizations"] = p.realizations;
  s["collisions"] = e.total_collisions;
  s["wall_seconds"] = e.wall_seconds;
  s["collisions_per_second"] = e.wall_seconds > 0 ? e.total_collisions / e.wall_seconds : 0.0;
  s["stop"] = to_string(e.first.stop.reason);
  s["stop_time"] = e.first.stop.time;
  if (e.first.stop.reason == particles::StopReason::collapse) s["collapse_position"] = e.first.stop.position;
  if (e.first.stop.reason == particles::StopReason::stall) s["stall_position"] = e.first.stop.position;
  if (p.solver == "events") {
    s["schedule"] = e.first.schedule.order;  // time windows, or the global queue
    if (!e.first.schedule.why_global.empty()) s["schedule_note"] = e.first.schedule.why_global;
  }
  if (!e.T.mean.empty()) {
    s["T_final"] = e.T.mean.back();
    s["n_bodies_final"] = e.n_bodies.mean.back();
  }
  state.report.push_back("## Particles\n");
  state.report.push_back("- " + std::to_string(state.scene.initial.N) + " particles, r = " + brief(p.r) +
                         ", delta = " + brief(p.delta) + " (" + p.subthreshold + " below it), " +
                         std::to_string(p.realizations) + " realization(s), solver `" + p.solver + "`.");
  state.report.push_back("- " + std::to_string(e.total_collisions) + " collisions in " +
                         brief(e.wall_seconds) + " s (" +
                         brief(std::round(s["collisions_per_second"].get<double>())) + " per second).");
  if (p.solver == "events")
    state.report.push_back(
        "- Event order: " + e.first.schedule.order +
        (e.first.schedule.why_global.empty() ? "" : " (" + e.first.schedule.why_global + ")") + ".");
  state.report.push_back("- Run ended: " + to_string(e.first.stop.reason) +
                         " at t = " + brief(e.first.stop.time) +
                         (e.first.stop.reason == particles::StopReason::collapse
                              ? " (inelastic collapse at x = " + brief(e.first.stop.position) + ")"
                          : e.first.stop.reason == particles::StopReason::stall
                              ? " (time stopped advancing at x = " + brief(e.first.stop.position) +
                                    " through rounding: results up to this time are kept)"
                              : "") +
                         ".\n");
}

}  // namespace

void run_particles_stage(RunState& state) {
  const auto& scene = state.scene;
  state.progress.stage("particles");
  const EnsembleResult e = particles::run_ensemble(scene.initial, scene.particles, state.progress.callback());
  state.progress.finish();
  write_series(state.h5, e);
  write_records(state.h5, e, scene.particles);
  const auto& stop = e.first.stop;
  state.h5.set_attribute("/particles", "stop_reason", to_string(stop.reason));
  state.h5.set_attribute("/particles", "stop_time", stop.time);
  if (stop.reason == particles::StopReason::collapse)
    state.h5.set_attribute("/particles", "collapse_x", stop.position);
  if (stop.reason == particles::StopReason::stall)
    state.h5.set_attribute("/particles", "stall_x", stop.position);
  summarize(state, e);
  state.final_bodies = e.first.final_state;
  state.final_time = e.first.stop.time;
  state.t_series = e.t;
  state.T_series = e.T.mean;
  if (e.first.histogram.bins > 0) {
    state.hist_z = bin_centres(e.first.histogram);
    state.hist_t = e.first.histogram.t;
    state.hist_density = e.histogram;
  }
}

}  // namespace shockgas::app
