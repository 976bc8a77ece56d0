// Interrupting a running realization (shockgas/core/interrupt.hpp): an abort request
// throws Interrupted from inside the time windows, on every thread of the team,
// and from the global queue; a checkpoint request ends the run at a safe point,
// whose state is the uninterrupted run's at that time.
#include <gtest/gtest.h>

#include "shockgas/core/initial_condition.hpp"
#include "shockgas/core/interrupt.hpp"
#include "shockgas/particles/simulate.hpp"

namespace shockgas::particles {
namespace {

class RunInterrupt : public ::testing::Test {
 protected:
  void SetUp() override { clear_interrupt(); }
  void TearDown() override { clear_interrupt(); }
};

InitialParams gas(std::size_t n) {
  InitialParams ip;
  ip.N = n;
  ip.positions = Positions::random;
  ip.seed = 17;
  return ip;
}

// A run that would go on for a long time: one sample at a far end, so the
// windows end only at their horizons; the wall limit only guards the test.
ParticleParams endless(Schedule schedule, std::size_t threads) {
  ParticleParams p;
  p.r = 0.9;
  p.delta = 1e-2;
  p.t_end = 1e9;
  p.samples = 1;
  p.clusters = false;
  p.schedule = schedule;
  p.threads = threads;
  p.max_wall_seconds = 120;
  return p;
}

// The progress callback runs at the engine's check points, inside the windows:
// the request is made there, during the run.
ProgressCallback request_at_first_report(InterruptMode mode) {
  return [mode](double, double, std::uint64_t) { request_interrupt(mode); };
}

TEST_F(RunInterrupt, AbortThrowsFromInsideTheWindowsOnTwoThreads) {
  EXPECT_THROW(
      simulate(gas(100000), 0, endless(Schedule::windows, 2), request_at_first_report(InterruptMode::abort)),
      Interrupted);
}

TEST_F(RunInterrupt, AbortThrowsFromTheGlobalQueue) {
  EXPECT_THROW(
      simulate(gas(100000), 0, endless(Schedule::global, 1), request_at_first_report(InterruptMode::abort)),
      Interrupted);
}

// Stopped on a checkpoint request, then the same run without one to the time it
// stopped at: the same collisions and the same state, to the bit (a safe point is
// a state the uninterrupted run passes through).
void expect_checkpoint_at_a_safe_point(Schedule schedule, std::size_t threads) {
  const InitialParams ip = gas(50000);
  ParticleParams p = endless(schedule, threads);
  const RunResult stopped = simulate(ip, 0, p, request_at_first_report(InterruptMode::checkpoint));
  clear_interrupt();
  ASSERT_EQ(stopped.stop.reason, StopReason::interrupted);
  ASSERT_GT(stopped.collisions, 0u);
  ASSERT_LT(stopped.stop.time, p.t_end);
  p.t_end = stopped.stop.time;
  p.max_wall_seconds = 0;
  const RunResult straight = simulate(ip, 0, p);
  ASSERT_EQ(straight.stop.reason, StopReason::completed);
  EXPECT_EQ(stopped.collisions, straight.collisions);
  for (auto column : {&Bodies::x, &Bodies::v, &Bodies::m})
    EXPECT_EQ(stopped.final_state.*column, straight.final_state.*column);
}

TEST_F(RunInterrupt, CheckpointStopsAtAWindowEnd) { expect_checkpoint_at_a_safe_point(Schedule::windows, 2); }
TEST_F(RunInterrupt, CheckpointStopsAtACheckPointOfTheGlobalQueue) {
  expect_checkpoint_at_a_safe_point(Schedule::global, 1);
}

TEST_F(RunInterrupt, CheckpointLeavesTheEnsemblesOtherRealizationsUnstarted) {
  // One thread: realization 0 stops at a safe point, 1 and 2 are never started.
  ParticleParams p = endless(Schedule::automatic, 1);
  p.realizations = 3;
  const EnsembleResult e = run_ensemble(gas(50000), p, request_at_first_report(InterruptMode::checkpoint));
  ASSERT_EQ(e.stops.size(), 3u);
  EXPECT_EQ(e.stops[0].reason, StopReason::interrupted);
  EXPECT_GT(e.stops[0].time, 0.0);
  for (std::size_t k : {1u, 2u}) {
    EXPECT_EQ(e.stops[k].reason, StopReason::interrupted);
    EXPECT_EQ(e.stops[k].time, 0.0);
  }
}

}  // namespace
}  // namespace shockgas::particles
