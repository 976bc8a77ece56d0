// The keys of summary.json, declared once: key, unit, meaning, and where each
// comes from in the run's results.
#include <cmath>

#include "shockgas/app/output/layout_declarations.hpp"
#include "shockgas/app/output/theory_scopes.hpp"
#include "shockgas/app/scene/scene_schema.hpp"
#include "shockgas/core/error.hpp"
#include "shockgas/core/initial_stream.hpp"
#include "shockgas/version.hpp"

namespace shockgas::app::layout {

namespace {

using Json = nlohmann::ordered_json;

Json finite_or_null(double x) { return std::isfinite(x) ? Json(x) : Json(nullptr); }

template <class F>
Emit always(F f) {
  return [f](const RunResults& r, Emitter& out) { out.json(f(r)); };
}

// f(particle results) -> Json, when particles ran.
template <class F>
Emit particle(F f) {
  return [f](const RunResults& r, Emitter& out) {
    if (r.particles) out.json(f(*r.particles, *r.scene));
  };
}

// What a summary key that echoes a scene key means: that key's doc, as declared
// beside its params struct (scene_schema.hpp), so that it is written once.
std::string as_used(const std::string& table, const std::string& name) {
  const TableSpec* t = find_table(table);
  const KeySpec* k = t ? t->find(name) : nullptr;
  if (!k) throw RunError("summary layout: no scene key " + table + "." + name);
  return "the scene key " + table + "." + name + " as used: " + k->info.doc;
}

std::vector<Declaration> provenance_and_initial() {
  const Part p = Part::provenance, i = Part::initial;
  auto initial = [](auto f) {
    return [f](const RunResults& r, Emitter& out) {
      if (r.initial) out.json(f(*r.initial));
    };
  };
  return {
      key(p, "scene", "", "the scene's name", "", always([](const RunResults& r) { return r.scene->name; })),
      key(p, "shockgas_version", "", "the program that wrote it", "",
          always([](const RunResults&) { return kVersion; })),
      key(p, "git_commit", "", "its commit", "", always([](const RunResults&) { return kGitCommit; })),
      key(p, "build", "", "the instruction set it was compiled for (SHOCKGAS_NATIVE)", "",
          always([](const RunResults&) { return kBuildTarget; })),
      key(p, "overrides", "", "the --set overrides, in order", "",
          always([](const RunResults& r) { return r.scene->overrides; })),
      key(i, "initial.N", "1", as_used("initial", "N"), "",
          initial([](const InitialCondition& c) { return c.params().N; })),
      key(i, "initial.length", "length", "domain length (L, or N for unit spacing; domain for expressions)",
          "", initial([](const InitialCondition& c) { return c.length(); })),
      key(i, "initial.positions", "",
          as_used("initial", "positions") + "; \"file\" where initial.file gives them", "",
          initial([](const InitialCondition& c) {
            const bool from_file = c.params().velocities == Velocities::file;
            return from_file ? std::string("file") : std::string(name_of(c.params().positions));
          })),
      key(i, "initial.velocities", "", as_used("initial", "velocities"), "",
          initial([](const InitialCondition& c) { return name_of(c.params().velocities); })),
      key(i, "initial.seed", "", as_used("initial", "seed"), "",
          initial([](const InitialCondition& c) { return c.params().seed; })),
      // Written with the particles' part: as realization 0 summed it while drawing
      // its bodies, else (a run resumed from a saved state) drawn again.
      key(Part::particles, "initial.temperature", "length^2/time^2", "temperature of realization 0",
          "when particles run",
          [](const RunResults& r, Emitter& out) {
            if (!r.initial || !r.particles) return;
            const std::optional<double>& drawn = r.particles->ensemble.first.initial_temperature;
            out.json(drawn ? *drawn : initial_temperature(*r.initial, 0));
          }),
  };
}

std::vector<Declaration> particles() {
  const Part p = Part::particles;
  using PR = ParticleResults;
  using StopReason = particles::StopReason;
  // f(realization 0's schedule) -> Json, when the event solver ran (null: nothing).
  auto events = [](auto f) {
    return [f](const RunResults& r, Emitter& out) {
      if (!r.particles || r.scene->particles.solver != particles::ParticleSolver::events) return;
      if (Json j = f(r.particles->ensemble.first.schedule); !j.is_null()) out.json(j);
    };
  };
  return {
      key(p, "particles.solver", "", as_used("particles", "solver"), "",
          particle([](const PR&, const Scene& s) { return name_of(s.particles.solver); })),
      key(p, "particles.r", "1", as_used("particles", "r"), "",
          particle([](const PR&, const Scene& s) { return s.particles.r; })),
      key(p, "particles.delta", "length/time", as_used("particles", "delta"), "",
          particle([](const PR&, const Scene& s) { return s.particles.delta; })),
      key(p, "particles.realizations", "1", as_used("particles", "realizations"), "",
          particle([](const PR&, const Scene& s) { return s.particles.realizations; })),
      key(p, "particles.min_cluster_particles", "1", as_used("particles", "min_cluster_particles"), "",
          particle([](const PR&, const Scene& s) { return s.particles.min_cluster_particles; })),
      key(p, "particles.collisions", "1", "total collisions of all realizations", "",
          particle([](const PR& pr, const Scene&) { return pr.ensemble.total_collisions; })),
      key(p, "particles.wall_seconds", "s",
          "wall-clock time of the ensemble (a resumed run: with the time its interrupted parts spent up to "
          "their last checkpoint)",
          "", particle([](const PR& pr, const Scene&) { return pr.ensemble.wall_seconds; })),
      key(p, "particles.collisions_per_second", "1/s", "collisions / wall_seconds", "",
          particle([](const PR& pr, const Scene&) {
            const auto& e = pr.ensemble;
            return e.wall_seconds > 0 ? static_cast<double>(e.total_collisions) / e.wall_seconds : 0.0;
          })),
      key(p, "parallel.ranks", "1", "processes of the MPI job that ran the realizations (1: one process)", "",
          particle([](const PR& pr, const Scene&) { return pr.parallel.ranks; })),
      key(p, "parallel.threads", "1", "threads of each process", "",
          particle([](const PR& pr, const Scene&) { return pr.parallel.threads; })),
      key(p, "parallel.shards", "1", "shards merged into this result", "after shockgas merge",
          [](const RunResults& r, Emitter& out) {
            if (r.particles && r.particles->parallel.shards > 0) out.json(r.particles->parallel.shards);
          }),
      key(p, "particles.stop", "",
          "how realization 0 ended (completed, collapse, rounding_stall, event_limit, wall_limit)", "",
          particle([](const PR& pr, const Scene&) { return to_string(pr.ensemble.first.stop.reason); })),
      key(p, "particles.stop_time", "time", "when it ended", "",
          particle([](const PR& pr, const Scene&) { return pr.ensemble.first.stop.time; })),
      key(p, "particles.collapse_position", "length", "where the inelastic collapse happened",
          "after a collapse",
          [](const RunResults& r, Emitter& out) {
            if (r.particles && r.particles->ensemble.first.stop.reason == StopReason::collapse)
              out.json(r.particles->ensemble.first.stop.position);
          }),
      key(p, "particles.stall_position", "length", "where time stopped advancing through rounding",
          "after a rounding stall",
          [](const RunResults& r, Emitter& out) {
            if (r.particles && r.particles->ensemble.first.stop.reason == StopReason::stall)
              out.json(r.particles->ensemble.first.stop.position);
          }),
      key(p, "particles.schedule", "",
          "how the event engine ordered the collisions: windows, global, or windows, then global",
          "with the event solver", events([](const particles::RunSchedule& s) { return s.order; })),
      key(p, "particles.schedule_note", "",
          "why the events (also) ran on the global queue, and what time windows would need there",
          "with the event solver, when not only windows", events([](const particles::RunSchedule& s) {
            return s.why_global.empty() ? Json() : Json(s.why_global);
          })),
      key(p, "particles.window_threads", "1",
          "threads that ran realization 0's time windows (particles.threads shared out among the "
          "realizations)",
          "with the event solver, on windows", events([](const particles::RunSchedule& s) {
            return s.order == "global" ? Json() : Json(s.threads);
          })),
      key(p, "particles.T_final", "length^2/time^2", "T at the last sample (ensemble mean)", "",
          [](const RunResults& r, Emitter& out) {
            if (r.particles && !r.particles->ensemble.T.mean.empty())
              out.json(r.particles->ensemble.T.mean.back());
          }),
      key(p, "particles.n_bodies_final", "1", "bodies at the last sample (ensemble mean)", "",
          [](const RunResults& r, Emitter& out) {
            if (r.particles && !r.particles->ensemble.T.mean.empty())
              out.json(r.particles->ensemble.n_bodies.mean.back());
          }),
  };
}

std::vector<Declaration> analysis() {
  const Part p = Part::analysis;
  auto fit = [](auto f) {
    return [f](const RunResults& r, Emitter& out) {
      if (r.particles && r.particles->cooling.fit)
        out.json(f(r.particles->cooling, *r.particles->cooling.fit));
    };
  };
  auto distribution = [](auto f) {
    return [f](const RunResults& r, Emitter& out) {
      if (!r.particles) return;
      const auto& a = r.particles->distribution;
      if (a.collapse_distance && a.not_determined.empty()) f(a, out);
    };
  };
  // Read off the T(t) curve, fitted or not.
  auto curve = [](auto f) {
    return [f](const RunResults& r, Emitter& out) {
      if (r.particles && !r.particles->cooling.local_exponent.empty()) out.json(f(r.particles->cooling));
    };
  };
  // A crossover's theory value, null where that theory does not hold for the scene.
  auto crossover_theory = [](auto f) {
    return [f](const RunResults& r, Emitter& out) {
      if (!r.particles || r.particles->cooling.local_exponent.empty()) return;
      if (law_scope(r, compare::Law::crossovers).holds)
        out.json(f(r.particles->cooling));
      else
        out.json(nullptr);
    };
  };
  using Cooling = compare::CoolingAnalysis;
  using Fit = compare::PowerLawFit;
  using Dist = compare::DistributionAnalysis;
  return {
      with_theory(key(p, "analysis.T_exponent", "1",
                      "fitted exponent of T(t) on analysis.T_fit_window: theory.sticky_cooling's window "
                      "where it holds, else [t_end / fit_window, t_end] from no earlier than a decade after "
                      "the scene's last crossover (compare::cooling_fit_scope)",
                      "where that window exists and holds 3 or more samples",
                      fit([](const Cooling&, const Fit& f) { return f.exponent; })),
                  compare::Law::sticky_cooling, "-2/3 (sticky gas, t_stick << t << N^(3/2))"),
      key(p, "analysis.T_exponent_error", "1",
          "its least-squares standard error, several times too small (correlated sample times): not an error "
          "bar; "
          "the error is analysis.T_exponent_jackknife_error",
          "", fit([](const Cooling&, const Fit& f) { return f.exponent_error; })),
      key(p, "analysis.T_fit_window", "time", "the fit window [t_min, t_max]", "",
          fit([](const Cooling&, const Fit& f) {
            return Json{f.t_min, f.t_max};
          })),
      with_theory(key(p, "analysis.t_dissip", "time",
                      "end of the elastic regime read off d ln T / d ln t (null: not crossed)", "",
                      curve([](const Cooling& a) { return finite_or_null(a.crossovers.t_dissip); })),
                  compare::Law::crossovers, "~ {analysis.t_dissip_theory}"),
      with_theory(key(p, "analysis.t_stick", "time",
                      "end of homogeneous cooling read off d ln T / d ln t (null: not crossed)", "",
                      curve([](const Cooling& a) { return finite_or_null(a.crossovers.t_stick); })),
                  compare::Law::crossovers, "~ {analysis.t_stick_theory}"),
      with_theory(key(p, "analysis.t_dissip_theory", "time",
                      "theory: end of the elastic regime, 1/eps, eps = (1 - r)/2 (null where that theory "
                      "does not hold, theory.crossovers)",
                      "", crossover_theory([](const Cooling& a) { return a.crossovers.t_dissip_theory; })),
                  compare::Law::crossovers, "1/eps"),
      with_theory(key(p, "analysis.t_stick_theory", "time",
                      "theory: end of homogeneous cooling, eps^(-3/2) (null where that theory does not hold, "
                      "theory.crossovers)",
                      "", crossover_theory([](const Cooling& a) { return a.crossovers.t_stick_theory; })),
                  compare::Law::crossovers, "eps^(-3/2)"),
      key(p, "analysis.cooling_law_not_determined", "", "why the cooling law could not be fitted",
          "when the scene leaves no fit window, or the data refuse it",
          [](const RunResults& r, Emitter& out) {
            if (r.particles && !r.particles->cooling.not_determined.empty())
              out.json(r.particles->cooling.not_determined);
          }),
      with_theory(key(p, "analysis.velocity_collapse_distance", "1",
                      "mean L1 distance between the scaled distributions of the late samples "
                      "(0 = perfect collapse, 2 = disjoint)",
                      "with 2 or more late samples",
                      [](const RunResults& r, Emitter& out) {
                        if (r.particles && r.particles->distribution.collapse_distance)
                          out.json(*r.particles->distribution.collapse_distance);
                      }),
                  compare::Law::velocity_scaling, "0 (one scaled distribution)"),
      key(p, "analysis.velocity_distribution_not_determined", "",
          "why the distribution could not be analysed", "when the data refuse it",
          [](const RunResults& r, Emitter& out) {
            if (r.particles && !r.particles->distribution.not_determined.empty())
              out.json(r.particles->distribution.not_determined);
          }),
      key(p, "analysis.velocity_tail_zmin", "length/time^(2/3)",
          "start of the tail fit: one standard deviation of z", "",
          distribution([](const Dist& a, Emitter& out) { out.json(a.tail_z_min); })),
      with_theory(key(p, "analysis.velocity_tail_exponent", "1",
                      "fitted a in Phi(z) ~ exp(-c |z|^a) (null: not determined)", "",
                      distribution([](const Dist& a, Emitter& out) {
                        out.json(a.tail.at_bound ? Json(nullptr) : Json(a.tail.exponent));
                      })),
                  compare::Law::velocity_scaling, "3"),
      key(p, "analysis.velocity_tail_exponent_error", "1", "its error (profile least squares)", "",
          distribution([](const Dist& a, Emitter& out) {
            if (!a.tail.at_bound) out.json(a.tail.exponent_error);
          })),
  };
}

}  // namespace

std::vector<Declaration> run_keys() {
  std::vector<Declaration> d = provenance_and_initial();
  append(d, particles());
  append(d, analysis());
  return d;
}

}  // namespace shockgas::app::layout
