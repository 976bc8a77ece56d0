// An abort request during a big run (label `slow`): N = 10^7 on two threads.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <iostream>
#include <thread>

#include "shockgas/core/initial_condition.hpp"
#include "shockgas/core/interrupt.hpp"
#include "shockgas/particles/simulate.hpp"

namespace shockgas::particles {
namespace {

using Clock = std::chrono::steady_clock;

TEST(RunInterruptSlow, AbortStopsTenMillionBodiesOnTwoThreadsPromptly) {
  clear_interrupt();
  InitialParams ip;
  ip.N = 10'000'000;
  ip.seed = 3;
  ParticleParams p;
  p.r = 0.9;
  p.delta = 1e-2;
  p.t_end = 1e6;  // far: the run is stopped long before
  p.samples = 1;  // the windows end only at their horizons (up to ~4 collisions per body: seconds)
  p.clusters = false;
  p.schedule = Schedule::windows;
  p.threads = 2;
  p.max_wall_seconds = 300;  // guards the test only

  // The request comes from another thread, as from a signal handler, once the
  // events run (the first progress report) and 1.5 s later, when a window
  // holds a few collisions per body.
  std::atomic<bool> running{false};
  Clock::time_point requested;
  std::thread requester([&] {
    while (!running) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    std::this_thread::sleep_for(std::chrono::milliseconds(1500));
    requested = Clock::now();
    request_interrupt(InterruptMode::abort);
  });
  bool interrupted = false;
  try {
    simulate(ip, 0, p, [&](double, double, std::uint64_t) { running = true; });
  } catch (const Interrupted&) {
    interrupted = true;
  }
  const Clock::time_point caught = Clock::now();
  requester.join();
  clear_interrupt();
  ASSERT_TRUE(interrupted);
  const double latency = std::chrono::duration<double>(caught - requested).count();
  std::cout << "abort latency at N = 10^7 on 2 threads: " << latency << " s\n";
  // Every member polls every 2^13 rounds of two steps (about a millisecond of
  // work; measured 5-9 ms from request to catch on the loaded shared machine).
  // Were only member 0 to poll, the other would run the rest of the window
  // alone: 0.06-1.0 s measured. The bound is the target, 0.1 s.
  EXPECT_LT(latency, 0.1);
}

}  // namespace
}  // namespace shockgas::particles
