#include "shockgas/particles/simulate.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>

#include "event_engine.hpp"
#include "hull_model.hpp"
#include "recorder.hpp"
#include "shockgas/core/error.hpp"
#include "shockgas/core/interrupt.hpp"
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

// Decides, every few thousand collisions, whether to go on: limits and progress.
struct Watch {
  const ParticleParams& p;
  const ProgressCallback& progress;
  Clock::time_point start = Clock::now();
  double last_report = 0;
  StopReason reason = StopReason::completed;

  double elapsed() const { return std::chrono::duration<double>(Clock::now() - start).count(); }
  bool operator()(double t, std::uint64_t collisions) {
    if (interrupt_requested() == InterruptMode::abort) return false;  // run_events throws Interrupted
    if (p.max_collisions > 0 && collisions >= p.max_collisions)
      return reason = StopReason::event_limit, false;
    const double s = elapsed();
    if (p.max_wall_seconds > 0 && s >= p.max_wall_seconds) return reason = StopReason::wall_limit, false;
    if (progress && s - last_report >= 0.1) {
      last_report = s;
      progress(work_fraction(t, p.t_end), t);
    }
    return true;
  }
};

// The engine's live bodies at time t as the recorder reads them: streamed, not copied.
template <bool Linked>
auto chain_view(const detail::EventEngine<Linked>& engine, double t) {
  return detail::make_chain_view(engine.alive(), [&engine, t](auto&& f) { engine.for_each_body(t, f); });
}

template <bool Linked>
detail::Counters counters(const detail::EventEngine<Linked>& e) {
  return {e.collisions(), e.count(CollisionKind::inelastic), e.count(CollisionKind::elastic),
          e.count(CollisionKind::merge), e.dissipated()};
}

CollisionRule rule_of(const ParticleParams& p) {
  return {p.r, p.delta, p.subthreshold == Subthreshold::sticky};
}

// Time windows over domains where they are exact (particles.schedule).
bool windows_possible(const Bodies& initial, const ParticleParams& p) {
  return equal_masses(initial) && detail::WindowScheduler::applicable(initial.size(), rule_of(p));
}

template <bool Linked>
RunResult run_events(const Bodies& initial, double L, bool ring, const ParticleParams& p,
                     const ProgressCallback& progress) {
  const CollisionRule rule = rule_of(p);
  const bool windows = !Linked && p.schedule != Schedule::global && windows_possible(initial, p);
  detail::Recorder recorder(p, initial.size(), L, ring);
  detail::EventEngine<Linked> engine(initial, L, ring, rule, !windows);
  std::optional<detail::WindowScheduler> scheduler;
  if constexpr (!Linked)
    if (windows) scheduler.emplace(engine);
  Watch watch{p, progress};
  auto advance = [&](double t) {
    if constexpr (!Linked)
      if (scheduler) return scheduler->run_until(t, watch);
    return engine.run_until(t, watch);
  };
  RunStop stop;
  for (double t = recorder.next_stop(); t != detail::Recorder::done; t = recorder.next_stop()) {
    const detail::EngineStop s = advance(t);
    if (s == detail::EngineStop::collapse)
      stop = {StopReason::collapse, engine.now(), engine.last_position()};
    if (s == detail::EngineStop::stall) stop = {StopReason::stall, engine.now(), engine.last_position()};
    if (s == detail::EngineStop::halted) stop = {watch.reason, engine.now(), 0.0};
    if (s != detail::EngineStop::reached) break;
    recorder.observe(t, chain_view(engine, t), counters(engine));
  }
  throw_if_aborted();
  if (stop.reason == StopReason::completed) stop.time = engine.now();
  RunResult out = recorder.finish(chain_view(engine, engine.now()), stop, counters(engine));
  out.wall_seconds = watch.elapsed();
  return out;
}

}  // namespace

void check_schedule(const Bodies& initial, const ParticleParams& p) {
  require(p.schedule != Schedule::windows || windows_possible(initial, p), "particles.schedule",
          name_of(p.schedule),
          "\"windows\" only for equal masses without merges or inelastic collapse (delta > 0 or r = 1), "
          "N >= 1024; else \"auto\" or \"global\"");
}

RunResult simulate(const Bodies& initial, double L, const ParticleParams& p,
                   const ProgressCallback& progress) {
  validate(p);
  const bool ring = p.geometry == Geometry::ring;
  check_bodies(initial, L, ring);
  require(!p.spacetime || initial.size() <= 100000, "particles.spacetime", std::string("true"),
          "a space-time record only for N <= 10^5");
  if (p.solver == ParticleSolver::hull) return detail::simulate_hull(initial, L, ring, p);
  check_schedule(initial, p);
  const CollisionRule rule = rule_of(p);
  if (rule.can_merge() || !equal_masses(initial)) return run_events<true>(initial, L, ring, p, progress);
  return run_events<false>(initial, L, ring, p, progress);
}

}  // namespace shockgas::particles
