#pragma once
// A run of the event engine advanced a step at a time, for a live view (the
// lab, docs/gallery.md): the engine of simulate() on its global queue, stopped
// and continued at any times. Where it stops changes no collision: at each time
// it reaches, its state is the final state of simulate() to that time with
// particles.schedule = "global", bit for bit (tests/particles/test_live_run.cpp).
//
//   LiveRun run(bodies, L, params);
//   for (double t = dt;; t += dt) {
//     while (!run.advance(t, 1 << 18).reached) draw(run.state());  // a budget per frame
//     draw(run.state());
//   }
#include <cstddef>
#include <cstdint>
#include <memory>

#include "shockgas/core/bodies.hpp"
#include "shockgas/particles/collision.hpp"
#include "shockgas/particles/params.hpp"
#include "shockgas/particles/run_result.hpp"

namespace shockgas::particles {

class LiveRun {
 public:
  // The engine loaded with `initial` (sorted by x, masses > 0; ring: x in
  // [0, L)) under params' collision rule and geometry (the event solver; the
  // other keys of params play no part). Throws InputError naming the key for
  // bad params or bodies, as simulate() does.
  LiveRun(const Bodies& initial, double L, const ParticleParams& params);
  ~LiveRun();
  LiveRun(LiveRun&&) noexcept;
  LiveRun& operator=(LiveRun&&) noexcept;

  struct Step {
    double time = 0;       // the time reached [time]
    bool reached = false;  // time == the requested t
    bool ended = false;    // collapse or rounding stall (stop says which): advance does nothing more
    RunStop stop;          // completed while the run goes on
  };
  // Every collision up to time t >= time(), or fewer: the run halts at the
  // first check point (every kGlobalQueueCheckEvery collisions) at which at
  // least `budget` collisions were made by this call, and then resumes from
  // there on the next call. A budget of 0 means no limit.
  Step advance(double t, std::uint64_t budget);

  double time() const;
  bool ended() const;
  // The live bodies at time(), sorted by x, ring positions in [0, L): as
  // RunResult::final_state.
  Bodies state() const;
  std::size_t alive() const;
  std::uint64_t collisions() const;  // all kinds
  std::uint64_t count(CollisionKind kind) const;
  double dissipated() const;  // kinetic energy lost [mass length^2/time^2]

  struct Impl;  // the engine, of the layout the bodies and the rule need (event_engine.hpp)

 private:
  std::unique_ptr<Impl> impl_;
};

}  // namespace shockgas::particles
