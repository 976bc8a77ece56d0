#pragma once
// Whether a run goes on (private to particles/): its limits, its progress
// reports and interruption requests (shockgas/core/interrupt.hpp), asked at the engine's
// check points.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>

#include "shockgas/core/interrupt.hpp"
#include "shockgas/core/progress.hpp"
#include "shockgas/particles/params.hpp"
#include "shockgas/particles/run_result.hpp"
#include "shockgas/particles/run_state.hpp"

namespace shockgas::particles::detail {

// Share of the work done at time t: collisions grow ~ t^(2/3) in the sticky regime.
inline double work_fraction(double t, double t_end) {
  return std::min(1.0, std::cbrt(t / t_end) * std::cbrt(t / t_end));
}

// operator() at points where the collision count is exact (the same for any
// number of threads) and the state is a safe point (the end of a time window
// or sub-window, or a check point of the global queue); tick() between them,
// from one thread, for the wall clock, progress and interruption only. Both
// return false to stop at the next safe point (reason says why) and throw
// Interrupted on an abort request.
struct RunWatch {
  using Clock = std::chrono::steady_clock;
  const ParticleParams& p;
  const ProgressCallback& progress;
  Clock::time_point start = Clock::now();
  double last_report = 0;
  std::uint64_t collisions_seen = 0;  // at the last safe point: what progress reports
  StopReason reason = StopReason::completed;
  // With saves (run_state.hpp): at each safe point when due, write_state is
  // handed to them; on a checkpoint request too, and then Interrupted is thrown.
  RunSaves* saves = nullptr;
  std::function<void(RunStateWriter&)> write_state{};

  double elapsed() const { return std::chrono::duration<double>(Clock::now() - start).count(); }
  bool operator()(double t, std::uint64_t collisions) {
    if (p.max_collisions > 0 && collisions >= p.max_collisions)
      return reason = StopReason::event_limit, false;
    collisions_seen = collisions;
    const bool go_on = tick(t);
    if (saves_on_request()) save_and_stop(t);
    if (saves && go_on && saves->due()) saves->save(t, work_fraction(t, p.t_end), write_state);
    return go_on;
  }
  // Collisions before the limit stops the run (the largest count when there is none).
  std::uint64_t collisions_left(std::uint64_t collisions) const {
    if (p.max_collisions == 0) return std::numeric_limits<std::uint64_t>::max();
    return collisions >= p.max_collisions ? 0 : p.max_collisions - collisions;
  }
  // Whether a checkpoint request stopped the run (tick() returned false) and it saves.
  bool saves_on_request() const { return saves && reason == StopReason::interrupted; }
  // Saves the run as it is now (at time t) and throws Interrupted: its result
  // would be a partial one; the save is what goes on.
  [[noreturn]] void save_and_stop(double t) {
    saves->save(t, work_fraction(t, p.t_end), write_state);
    throw Interrupted(interrupt_signal());
  }
  bool tick(double t) {
    if (!interruption()) return false;
    const double s = elapsed();
    if (p.max_wall_seconds > 0 && s >= p.max_wall_seconds) return reason = StopReason::wall_limit, false;
    if (progress && s - last_report >= 0.1) {
      last_report = s;
      progress(work_fraction(t, p.t_end), t, collisions_seen);
    }
    return true;
  }
  // False on a checkpoint request; throws Interrupted on an abort request.
  bool interruption() {
    const InterruptMode mode = interrupt_requested();
    if (mode == InterruptMode::none) [[likely]]
      return true;
    throw_if_aborted();
    reason = StopReason::interrupted;
    return false;
  }
};

}  // namespace shockgas::particles::detail
