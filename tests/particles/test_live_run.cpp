// LiveRun (shockgas/particles/live_run.hpp), the engine of the lab advanced a
// frame at a time: wherever it stops, its state at a time it reaches is the
// final state of simulate() to that time on the global queue, bit for bit, with
// the same counts of collisions and the same dissipated energy; on the ring and
// the line, with bounces (r = 0.5, elastic or sticky below delta) and merges
// (r = 0), advanced in frames and with budgets small enough to stop frames midway.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <vector>

#include "shockgas/core/error.hpp"
#include "shockgas/core/initial_condition.hpp"
#include "shockgas/particles/live_run.hpp"
#include "shockgas/particles/simulate.hpp"

namespace shockgas::particles {
namespace {

bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() &&
         (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
}

struct Case {
  double r;
  bool sticky;
  bool line;
  std::uint64_t seed;
};

ParticleParams params_of(const Case& c, double t_end) {
  ParticleParams p;
  p.r = c.r;
  p.delta = 1e-2;
  p.subthreshold = c.sticky ? Subthreshold::sticky : Subthreshold::elastic;
  p.geometry = c.line ? Geometry::line : Geometry::ring;
  p.schedule = Schedule::global;
  p.t_end = t_end;
  p.samples = 4;
  p.clusters = false;
  p.threads = 1;
  return p;
}

class LiveRunMatchesSimulate : public ::testing::TestWithParam<Case> {};

TEST_P(LiveRunMatchesSimulate, AtEveryFrameBitForBit) {
  const Case c = GetParam();
  InitialParams init;
  init.N = c.r == 0 ? 40000 : 3000;  // merges end at N - 1: enough of them to fill a budget
  init.seed = c.seed;
  const Bodies bodies = make_initial_bodies(init, 0);
  const double L = domain_length(init);
  const std::vector<double> frames = {1.5, 3.0, 12.0, 40.0};
  LiveRun run(bodies, L, params_of(c, frames.back()));
  int steps = 0;
  for (const double t : frames) {
    LiveRun::Step s;
    // A budget of 5000: a frame stops at the first check point past it (kGlobalQueueCheckEvery) and resumes.
    do s = run.advance(t, 5000), ++steps;
    while (!s.reached && !s.ended);
    ASSERT_FALSE(s.ended) << "t = " << t;
    EXPECT_EQ(run.time(), t);
    const RunResult whole = simulate(bodies, L, params_of(c, t));
    const Bodies state = run.state();
    EXPECT_TRUE(same_bits(state.x, whole.final_state.x)) << "x at t = " << t;
    EXPECT_TRUE(same_bits(state.v, whole.final_state.v)) << "v at t = " << t;
    EXPECT_TRUE(same_bits(state.m, whole.final_state.m)) << "m at t = " << t;
    EXPECT_EQ(run.collisions(), whole.collisions) << "t = " << t;
    EXPECT_EQ(run.alive(), whole.final_state.size());
  }
  EXPECT_GT(steps, static_cast<int>(frames.size()))
      << "the budget never stopped a frame: no resumption was checked";
  EXPECT_GT(run.collisions(), 10000u);
}

INSTANTIATE_TEST_SUITE_P(Rules, LiveRunMatchesSimulate,
                         ::testing::Values(Case{0.0, false, false, 1}, Case{0.5, false, false, 2},
                                           Case{0.5, true, false, 3}, Case{0.0, false, true, 4},
                                           Case{0.5, false, true, 5}));

TEST(LiveRun, RefusesWhatSimulateRefuses) {
  InitialParams init;
  init.N = 10;
  const Bodies bodies = make_initial_bodies(init, 0);
  ParticleParams p;
  p.r = 1.5;
  EXPECT_THROW(LiveRun(bodies, domain_length(init), p), InputError);
  p.r = 0.5;
  p.solver = ParticleSolver::hull;
  EXPECT_THROW(LiveRun(bodies, domain_length(init), p), InputError);
  p.solver = ParticleSolver::events;
  LiveRun run(bodies, domain_length(init), p);
  run.advance(2.0, 0);
  EXPECT_THROW(run.advance(1.0, 0), InputError);  // time runs forward only
}

}  // namespace
}  // namespace shockgas::particles
