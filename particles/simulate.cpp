#include "shockgas/particles/simulate.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>

#include "engine_state.hpp"
#include "event_engine.hpp"
#include "hull_model.hpp"
#include "recorder.hpp"
#include "shockgas/core/cores.hpp"
#include "shockgas/core/error.hpp"
#include "shockgas/core/initial_stream.hpp"
#include "window_scheduler.hpp"

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
  }
  return "unknown";
}

namespace {

using Clock = std::chrono::steady_clock;

// Checks every body; the error message is built only for a failing one.
void check_bodies(const Bodies& b, double L, bool ring) {
  require(b.size() >= 2 && b.v.size() == b.size() && b.m.size() == b.size(), "initial.N", b.size(),
          "at least 2 bodies with x, v and m each");
  require(std::isfinite(L) && L > 0, "initial.L", L, "a finite length > 0");
  for (std::size_t i = 0; i < b.size(); ++i) {
    const bool finite = std::isfinite(b.x[i]) && std::isfinite(b.v[i]);
    const bool mass = std::isfinite(b.m[i]) && b.m[i] > 0;
    const bool sorted = i == 0 || b.x[i - 1] <= b.x[i];
    const bool inside = !ring || (b.x[i] >= 0 && b.x[i] < L);
    if (finite && mass && sorted && inside) continue;
    require(finite, "initial.bodies", b.x[i], "finite x and v");
    require(mass, "initial.bodies.m", b.m[i], "finite masses > 0");
    require(sorted, "initial.bodies.x", b.x[i], "positions sorted ascending");
    require(inside, "initial.bodies.x", b.x[i], "positions in [0, L) on a ring");
  }
}

bool equal_masses(const Bodies& b) {
  return std::all_of(b.m.begin(), b.m.end(), [&](double m) { return m == b.m[0]; });
}

// Share of the work done at time t: collisions grow ~ t^(2/3) in the sticky regime.
double work_fraction(double t, double t_end) {
  return std::min(1.0, std::cbrt(t / t_end) * std::cbrt(t / t_end));
}

// Decides whether to go on: limits and progress. operator() at points where the
// collision count is exact (the same for any number of threads); tick() between
// them, from one thread, for the wall clock and progress only.
struct Watch {
  const ParticleParams& p;
  const ProgressCallback& progress;
  Clock::time_point start = Clock::now();
  double last_report = 0;
  StopReason reason = StopReason::completed;

  double elapsed() const { return std::chrono::duration<double>(Clock::now() - start).count(); }
  bool operator()(double t, std::uint64_t collisions) {
    if (p.max_collisions > 0 && collisions >= p.max_collisions)
      return reason = StopReason::event_limit, false;
    return tick(t);
  }
  bool tick(double t) {
    const double s = elapsed();
    if (p.max_wall_seconds > 0 && s >= p.max_wall_seconds) return reason = StopReason::wall_limit, false;
    if (progress && s - last_report >= 0.1) {
      last_report = s;
      progress(work_fraction(t, p.t_end), t);
    }
    return true;
  }
};

template <bool Linked>
detail::ChainState chain_state(const detail::EventEngine<Linked>& engine, double t) {
  detail::ChainState s;
  s.reserve(engine.alive());
  engine.for_each_body(t, [&](std::size_t i, double x, double v, double m) { s.push_back(i, x, v, m); });
  return s;
}

template <bool Linked>
detail::Counters counters(const detail::EventEngine<Linked>& e) {
  return {e.collisions(), e.count(CollisionKind::inelastic), e.count(CollisionKind::elastic),
          e.count(CollisionKind::merge), e.dissipated()};
}

CollisionRule rule_of(const ParticleParams& p) { return {p.r, p.delta, p.subthreshold == "sticky"}; }

// The engine's layout: links and masses for merges or unequal masses.
bool linked(const CollisionRule& rule, bool equal_masses) { return rule.can_merge() || !equal_masses; }

// Time windows over domains where they are exact (particles.schedule).
bool windows_possible(std::size_t n, bool equal_masses, const ParticleParams& p) {
  return detail::window_obstacle(n, equal_masses, rule_of(p)).empty();
}

void check_schedule(std::size_t n, bool equal_masses, const ParticleParams& p) {
  require(p.schedule != "windows" || windows_possible(n, equal_masses, p), "particles.schedule", p.schedule,
          "\"windows\" only where every collision keeps the velocities in their range (equal masses "
          "without merges, or merges only: r = 0 with delta = 0 or sticky sub-threshold), without "
          "inelastic collapse (delta > 0 or r = 0, 1), N >= 1024; else \"auto\" or \"global\"");
}

std::size_t threads_of(const ParticleParams& p) { return p.threads > 0 ? p.threads : usable_cores(); }

// One run of the engine from n bodies written by fill (see EventEngine). With a
// sink, the snapshots and the final state go to it instead of the recorder.
template <bool Linked, class Fill>
RunResult run_events(std::size_t n, Fill&& fill, double L, bool ring, bool equal_masses,
                     const ParticleParams& p, const ProgressCallback& progress, const StateSink* sink) {
  const CollisionRule rule = rule_of(p);
  const bool windows = p.schedule != "global" && windows_possible(n, equal_masses, p);
  ParticleParams recorded = p;
  std::vector<double> snapshots;
  if (sink)
    snapshots = p.snapshots, recorded.snapshots.clear(), std::sort(snapshots.begin(), snapshots.end());
  detail::Recorder recorder(recorded, n, L, ring);
  detail::EventEngine<Linked> engine(n, L, ring, rule, fill);
  std::optional<detail::WindowScheduler<Linked>> scheduler;
  if (windows) {
    scheduler.emplace(engine, threads_of(p));
  } else {
    engine.use_global_queue();
  }
  Watch watch{p, progress};
  auto advance = [&](double t) {
    return scheduler ? scheduler->run_until(t, watch) : engine.run_until(t, watch);
  };
  std::size_t next_snapshot = 0;
  auto next_stop = [&] {
    const double t = recorder.next_stop();
    return next_snapshot < snapshots.size() ? std::min(t, snapshots[next_snapshot]) : t;
  };
  RunStop stop;
  for (double t = next_stop(); t != detail::Recorder::done; t = next_stop()) {
    const detail::EngineStop s = advance(t);
    if (s == detail::EngineStop::collapse)
      stop = {StopReason::collapse, engine.now(), engine.last_position()};
    if (s == detail::EngineStop::stall) stop = {StopReason::stall, engine.now(), engine.last_position()};
    if (s == detail::EngineStop::halted) stop = {watch.reason, engine.now(), 0.0};
    if (s != detail::EngineStop::reached) break;
    if (recorder.next_stop() <= t) recorder.observe(t, chain_state(engine, t), counters(engine));
    for (; next_snapshot < snapshots.size() && snapshots[next_snapshot] <= t; ++next_snapshot)
      if (sink->snapshot) sink->snapshot(next_snapshot, t, detail::EngineState<Linked>(engine, t));
  }
  if (stop.reason == StopReason::completed) stop.time = engine.now();
  if (sink && sink->final_state)
    sink->final_state(engine.now(), detail::EngineState<Linked>(engine, engine.now()));
  RunResult out = recorder.finish(sink ? detail::ChainState{} : chain_state(engine, engine.now()), stop,
                                  counters(engine));
  out.wall_seconds = watch.elapsed();
  if (scheduler) {
    out.schedule.threads = scheduler->threads();
    out.schedule.order = scheduler->on_global_queue() ? "windows, then global" : "windows";
    out.schedule.why_global = scheduler->why_global();
  } else {
    out.schedule.why_global = p.schedule == "global" ? "particles.schedule = \"global\""
                                                     : detail::window_obstacle(n, equal_masses, rule);
  }
  return out;
}

template <class Fill>
RunResult run_events(std::size_t n, Fill&& fill, double L, bool ring, bool equal_masses,
                     const ParticleParams& p, const ProgressCallback& progress, const StateSink* sink) {
  if (linked(rule_of(p), equal_masses))
    return run_events<true>(n, fill, L, ring, equal_masses, p, progress, sink);
  return run_events<false>(n, fill, L, ring, equal_masses, p, progress, sink);
}

void check_params(std::size_t n, const ParticleParams& p) {
  validate(p);
  require(!p.spacetime || n <= 100000, "particles.spacetime", std::string("true"),
          "a space-time record only for N <= 10^5");
}

}  // namespace

void check_schedule(const Bodies& initial, const ParticleParams& p) {
  check_schedule(initial.size(), equal_masses(initial), p);
}

void check_schedule(const InitialParams& initial, const ParticleParams& p) {
  if (InitialStream::streamable(initial)) return check_schedule(initial.N, true, p);
  check_schedule(make_initial_bodies(initial, 0), p);
}

namespace {

RunResult simulate_bodies(const Bodies& initial, double L, const ParticleParams& p,
                          const ProgressCallback& progress, const StateSink* sink) {
  check_params(initial.size(), p);
  const bool ring = p.geometry == "ring";
  check_bodies(initial, L, ring);
  if (p.solver == "hull") return detail::simulate_hull(initial, L, ring, p);
  const bool equal = equal_masses(initial);
  check_schedule(initial.size(), equal, p);
  auto fill = [&](std::size_t first, std::size_t count, double* x, double* v, double* m) {
    std::copy_n(initial.x.begin() + first, count, x);
    std::copy_n(initial.v.begin() + first, count, v);
    std::copy_n(initial.m.begin() + first, count, m);
  };
  return run_events(initial.size(), fill, L, ring, equal, p, progress, sink);
}

}  // namespace

RunResult simulate(const Bodies& initial, double L, const ParticleParams& p,
                   const ProgressCallback& progress) {
  return simulate_bodies(initial, L, p, progress, nullptr);
}

RunResult simulate(const InitialParams& initial, std::uint64_t realization, const ParticleParams& p,
                   const ProgressCallback& progress, const StateSink* sink) {
  validate(initial);
  if (!InitialStream::streamable(initial) || p.solver == "hull")
    return simulate_bodies(make_initial_bodies(initial, realization), domain_length(initial), p, progress,
                           sink);
  check_params(initial.N, p);
  check_schedule(initial.N, true, p);
  InitialStream stream(initial, realization);
  auto fill = [&](std::size_t, std::size_t count, double* x, double* v, double* m) {
    stream.next(count, x, v, m);
  };
  return run_events(initial.N, fill, domain_length(initial), p.geometry == "ring", true, p, progress, sink);
}

}  // namespace shockgas::particles
