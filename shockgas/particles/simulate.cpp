#include "shockgas/particles/simulate.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "shockgas/core/cores.hpp"
#include "shockgas/core/error.hpp"
#include "shockgas/core/initial_stream.hpp"
#include "shockgas/particles/chain_view.hpp"
#include "shockgas/particles/event_engine.hpp"
#include "shockgas/particles/hull_model.hpp"
#include "shockgas/particles/recorder.hpp"
#include "shockgas/particles/run_state_io.hpp"
#include "shockgas/particles/run_watch.hpp"
#include "shockgas/particles/window_scheduler.hpp"

namespace shockgas::particles {

std::string to_string(StopReason reason) {
  switch (reason) {
    case StopReason::completed:
      return "completed";
    case StopReason::collapse:
      return "collapse";
    case StopReason::event_limit:
      return "event_limit";
    case StopReason::wall_limit:
      return "wall_limit";
    case StopReason::stall:
      return "rounding_stall";
    case StopReason::interrupted:
      return "interrupted";
  }
  return "unknown";
}

namespace {

// Checks every body; the error message is built only for a failing one.
void check_bodies(const Bodies& b, double L, bool ring) {
  require(b.size() >= 2 && b.v.size() == b.size() && b.m.size() == b.size(), "initial.N", b.size(),
          "at least 2 bodies with x, v and m each");
  require(std::isfinite(L) && L > 0, "initial.L", L, "a finite length > 0 (0: the number of bodies)");
  for (std::size_t i = 0; i < b.size(); ++i) {
    const bool finite = std::isfinite(b.x[i]) && std::isfinite(b.v[i]);
    const bool mass = std::isfinite(b.m[i]) && b.m[i] > 0;
    const bool sorted = i == 0 || b.x[i - 1] <= b.x[i];
    const bool inside = !ring || (b.x[i] >= 0 && b.x[i] < L);
    if (finite && mass && sorted && inside) continue;
    require_finite_body(b, i, "initial.bodies");
    const std::string x = "initial.bodies.x[" + std::to_string(i) + "]";
    require(sorted, x, b.x[i], "positions sorted ascending");
    require(
        inside, x, b.x[i],
        "positions in [0, L) on a ring (L = " + to_text(L) + ": initial.L, or initial.N where that is 0)");
  }
}

bool equal_masses(const Bodies& b) {
  return std::all_of(b.m.begin(), b.m.end(), [&](double m) { return m == b.m[0]; });
}

template <bool Linked>
detail::Counters counters(const detail::EventEngine<Linked>& e) {
  return {e.collisions(), e.count(CollisionKind::inelastic), e.count(CollisionKind::elastic),
          e.count(CollisionKind::merge), e.dissipated()};
}

// The engine's layout: links and masses for merges or unequal masses.
bool linked(const CollisionRule& rule, bool equal_masses) { return rule.can_merge() || !equal_masses; }

// Time windows over domains where they are exact (particles.schedule).
bool windows_possible(std::size_t n, bool equal_masses, const ParticleParams& p) {
  return detail::window_obstacle(n, equal_masses, collision_rule(p)).empty();
}

void check_schedule(std::size_t n, bool equal_masses, const ParticleParams& p) {
  require(p.schedule != Schedule::windows || windows_possible(n, equal_masses, p), "particles.schedule",
          name_of(p.schedule),
          "\"windows\" only where every collision keeps the velocities in their range (equal masses "
          "without merges, or merges only: r = 0), without "
          "inelastic collapse (delta > 0 or r = 0, 1), N >= 1024; else \"auto\" or \"global\"");
}

std::size_t threads_of(const ParticleParams& p) { return p.threads > 0 ? p.threads : usable_cores(); }

// How an engine run ended.
RunStop stop_of(detail::EngineStop s, double now, double position, StopReason watched) {
  switch (s) {
    case detail::EngineStop::collapse:
      return {StopReason::collapse, now, position};
    case detail::EngineStop::stall:
      return {StopReason::stall, now, position};
    case detail::EngineStop::halted:
      return {watched, now, 0.0};
    case detail::EngineStop::reached:
      break;
  }
  return {StopReason::completed, now, 0.0};
}

// What the summary says about the order of events.
template <class Scheduler>
RunSchedule schedule_of(const Scheduler* scheduler, std::size_t n, bool equal_masses,
                        const ParticleParams& p) {
  RunSchedule s;
  if (scheduler) {
    s.threads = scheduler->threads();
    s.order = scheduler->on_global_queue() ? "windows, then global" : "windows";
    s.why_global = scheduler->why_global();
  } else {
    s.why_global = p.schedule == Schedule::global
                       ? "particles.schedule = \"global\""
                       : detail::window_obstacle(n, equal_masses, collision_rule(p));
  }
  return s;
}

// The whole state of a run at a safe point (run_state.hpp), and back.
template <bool Linked>
void save_run(RunStateWriter& out, const detail::EventEngine<Linked>& engine,
              const detail::WindowScheduler<Linked>* scheduler, const detail::Recorder& recorder) {
  detail::StateIo::save(engine, out);
  detail::put(out, scheduler != nullptr);
  if (scheduler) detail::StateIo::save(*scheduler, out);
  recorder.save(out);
}
template <bool Linked>
void restore_run(RunStateReader& in, detail::EventEngine<Linked>& engine,
                 detail::WindowScheduler<Linked>* scheduler, detail::Recorder& recorder) {
  detail::StateIo::restore(engine, in);
  detail::expect(in, scheduler != nullptr, "schedule (windows or the global queue)");
  if (scheduler) detail::StateIo::restore(*scheduler, in);
  recorder.restore(in);
  if (in.remaining() != 0) throw RunError("a saved run state: bytes after its end");
}

// One run of the engine from n bodies written by fill (see EventEngine), their
// mean mass mean_mass, or continued from a saved state (checkpoints->resume).
template <bool Linked, class Fill>
RunResult run_events(std::size_t n, Fill&& fill, double L, bool ring, bool equal_masses, double mean_mass,
                     const ParticleParams& p, const ProgressCallback& progress, const StateSink* sink,
                     const RunCheckpoints& checkpoints) {
  using Engine = detail::EventEngine<Linked>;
  const bool windows = p.schedule != Schedule::global && windows_possible(n, equal_masses, p);
  detail::Recorder recorder(p, n, L, ring, mean_mass, sink);
  RunStateReader* resume = checkpoints.resume;
  Engine engine =
      resume ? Engine(n, L, ring, collision_rule(p)) : Engine(n, L, ring, collision_rule(p), fill);
  std::optional<detail::WindowScheduler<Linked>> scheduler;
  if (windows)
    scheduler.emplace(engine, threads_of(p));
  else if (!resume)
    engine.use_global_queue();
  detail::RunWatch watch{p, progress};
  if (resume) {
    restore_run(*resume, engine, scheduler ? &*scheduler : nullptr, recorder);
    watch.collisions_seen = engine.collisions();
    if (progress) progress(detail::work_fraction(engine.now(), p.t_end), engine.now(), engine.collisions());
  }
  watch.saves = checkpoints.saves;
  watch.write_state = [&](RunStateWriter& out) {
    save_run(out, engine, scheduler ? &*scheduler : nullptr, recorder);
  };
  RunStop stop;
  for (double t = recorder.next_stop(); t != detail::Recorder::done; t = recorder.next_stop()) {
    if (scheduler && !scheduler->on_global_queue()) {
      // Samples measured per domain on the way, as long as the windows run.
      const std::vector<double> times = recorder.samples_in_parts();
      if (!times.empty()) {
        detail::SampleBatch batch(
            times, [&](double ts) { return recorder.sample_spec(ts); },
            [&](double ts, const detail::SampleMoments& m, std::size_t clusters) {
              recorder.observe_sample(ts, m, clusters, counters(engine));
            });
        const detail::EngineStop s = scheduler->run_sampled(times.back(), watch, batch);
        stop = stop_of(s, engine.now(), engine.last_position(), watch.reason);
        if (s != detail::EngineStop::reached) break;
        continue;
      }
    }
    const detail::EngineStop s = scheduler ? scheduler->run_until(t, watch) : engine.run_until(t, watch);
    stop = stop_of(s, engine.now(), engine.last_position(), watch.reason);
    if (s != detail::EngineStop::reached) break;
    recorder.observe(t, detail::engine_chain_view(engine, t), counters(engine));
  }
  stop.time = engine.now();
  RunResult out = recorder.finish(detail::engine_chain_view(engine, engine.now()), stop, counters(engine));
  out.wall_seconds = watch.elapsed();
  out.schedule = schedule_of(scheduler ? &*scheduler : nullptr, n, equal_masses, p);
  return out;
}

template <class Fill>
RunResult run_events(std::size_t n, Fill&& fill, double L, bool ring, bool equal_masses, double mean_mass,
                     const ParticleParams& p, const ProgressCallback& progress, const StateSink* sink,
                     const RunCheckpoints& checkpoints) {
  if (linked(collision_rule(p), equal_masses))
    return run_events<true>(n, fill, L, ring, equal_masses, mean_mass, p, progress, sink, checkpoints);
  return run_events<false>(n, fill, L, ring, equal_masses, mean_mass, p, progress, sink, checkpoints);
}

void check_params(std::size_t n, const ParticleParams& p) {
  validate(p);
  require(!p.spacetime || n <= 100000, "particles.spacetime", std::string("true"),
          "a space-time record only for N <= 10^5");
}

// The engine from a stream of bodies; `bodies` the same bodies whole, if at hand.
RunResult run_stream(InitialStream& stream, double L, const Bodies* bodies, const ParticleParams& p,
                     const ProgressCallback& progress, const StateSink* sink,
                     const RunCheckpoints& checkpoints) {
  const bool equal = !bodies || equal_masses(*bodies);
  check_schedule(stream.size(), equal, p);
  TemperatureSums drawn;
  auto fill = [&](std::size_t, std::size_t count, double* x, double* v, double* m) {
    stream.next(count, x, v, m);
    drawn.add(v, m, count);
  };
  RunResult out = run_events(stream.size(), fill, L, p.geometry == Geometry::ring, equal, stream.mean_mass(),
                             p, progress, sink, checkpoints);
  // A resumed run drew nothing: its bodies are drawn again for their temperature alone.
  if (checkpoints.resume)
    read_in_chunks(stream, [&](const double*, const double* v, const double* m, std::size_t count) {
      drawn.add(v, m, count);
    });
  out.initial_temperature = drawn.temperature();
  return out;
}

// The hull solver has no safe points inside a run (run_state.hpp).
void check_no_state(const RunCheckpoints& checkpoints) {
  if (checkpoints.resume)
    throw RunError(
        "a saved run state given to the hull solver, which never saves one (particles.solver = \"hull\")");
}

RunResult simulate_bodies(const Bodies& initial, double L, const ParticleParams& p,
                          const ProgressCallback& progress, const StateSink* sink,
                          const RunCheckpoints& checkpoints) {
  check_params(initial.size(), p);
  const bool ring = p.geometry == Geometry::ring;
  check_bodies(initial, L, ring);
  if (chosen_solver(p) == ParticleSolver::hull) {
    check_no_state(checkpoints);
    return detail::simulate_hull(initial, L, ring, p, sink);
  }
  InitialStream stream(initial);
  return run_stream(stream, L, &initial, p, progress, sink, checkpoints);
}

}  // namespace

void check_schedule(const Bodies& initial, const ParticleParams& p) {
  check_schedule(initial.size(), equal_masses(initial), p);
}

double bytes_per_body(const ParticleParams& p, bool equal_masses) {
  if (chosen_solver(p) == ParticleSolver::hull) return 20;
  return linked(collision_rule(p), equal_masses) ? 52 : 40;
}

// Bodies drawn on the fly have unit masses.
void check_schedule(const InitialCondition& initial, const ParticleParams& p) {
  if (initial.holds_bodies()) return check_schedule(initial.bodies(), p);
  check_schedule(initial.params().N, true, p);
}

RunResult simulate(const Bodies& initial, double L, const ParticleParams& p, const ProgressCallback& progress,
                   const StateSink* sink, const RunCheckpoints& checkpoints) {
  return simulate_bodies(initial, ring_length(L, initial.size()), p, progress, sink, checkpoints);
}

RunResult simulate(const InitialCondition& initial, std::uint64_t realization, const ParticleParams& p,
                   const ProgressCallback& progress, const StateSink* sink,
                   const RunCheckpoints& checkpoints) {
  if (initial.holds_bodies() && (realization == 0 || !initial.depends_on_realization()))
    return simulate_bodies(initial.bodies(), initial.length(), p, progress, sink, checkpoints);
  check_params(initial.params().N, p);
  InitialStream stream = stream_realization(initial, realization);
  if (chosen_solver(p) == ParticleSolver::hull) {
    check_no_state(checkpoints);
    return detail::simulate_hull(stream, initial.length(), p.geometry == Geometry::ring, p, sink);
  }
  return run_stream(stream, initial.length(), nullptr, p, progress, sink, checkpoints);
}

RunResult simulate(const InitialParams& initial, std::uint64_t realization, const ParticleParams& p,
                   const ProgressCallback& progress, const StateSink* sink,
                   const RunCheckpoints& checkpoints) {
  return simulate(InitialCondition(initial, InitialCondition::Keep::stream), realization, p, progress, sink,
                  checkpoints);
}

}  // namespace shockgas::particles
