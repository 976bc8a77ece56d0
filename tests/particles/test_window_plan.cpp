// The cuts of a window plan (shockgas/particles/window_plan.hpp), refined: the candidates
// near every fine_bodies-th pair that surely stay open for the whole plan are
// added. Every cut must hold until the plan's horizon, or a collision across it
// would be missed: the windows with every plan refined give the global queue's
// collisions and final state to the bit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include "engine_fixtures.hpp"
#include "shockgas/core/initial_condition.hpp"
#include "shockgas/particles/run_watch.hpp"
#include "shockgas/particles/window_scheduler.hpp"

namespace shockgas::particles::detail {
namespace {

Bodies gas(std::size_t n) {
  InitialParams ip;
  ip.N = n;
  ip.positions = Positions::random;
  ip.velocities = Velocities::uniform;
  ip.seed = 23;
  return make_initial_bodies(ip);
}

struct Final {
  std::uint64_t collisions = 0;
  std::vector<double> x, v, m;
};

template <bool Linked>
Final final_of(const EventEngine<Linked>& e, double t) {
  Final f{e.collisions(), {}, {}, {}};
  e.for_each_body(t, [&](std::size_t, double x, double v, double m) {
    f.x.push_back(x), f.v.push_back(v), f.m.push_back(m);
  });
  return f;
}

// Windows whose every plan is refined, from bodies b to t on 1, 2 and 3 threads:
// the global queue's collisions (more than min_collisions) and final state to the bit.
template <bool Linked>
void expect_refined_windows_exact(const Bodies& b, bool ring, const CollisionRule& rule, double t,
                                  std::uint64_t min_collisions) {
  // The run's own watch, without limits, saves or progress.
  const ParticleParams unlimited;
  const ProgressCallback no_progress;
  RunWatch watch{unlimited, no_progress};
  EventEngine<Linked> global = engine_of<Linked>(b, ring, rule);
  global.use_global_queue();
  ASSERT_EQ(global.run_until(t, watch), EngineStop::reached);
  const Final a = final_of(global, t);
  ASSERT_GT(a.collisions, min_collisions);
  for (std::size_t threads : {1, 2, 3}) {
    EventEngine<Linked> windowed = engine_of<Linked>(b, ring, rule);
    WindowScheduler<Linked> scheduler(windowed, threads, 0.0);
    ASSERT_EQ(scheduler.run_until(t, watch), EngineStop::reached);
    ASSERT_FALSE(scheduler.on_global_queue()) << scheduler.why_global();
    const Final w = final_of(windowed, t);
    EXPECT_EQ(w.collisions, a.collisions) << threads << " threads";
    EXPECT_EQ(w.x, a.x) << threads << " threads";
    EXPECT_EQ(w.v, a.v) << threads << " threads";
    EXPECT_EQ(w.m, a.m) << threads << " threads";
  }
}

TEST(WindowPlanner, RefiningAddsCutsAndKeepsTheCoarseOnes) {
  const Bodies b = gas(1 << 15);
  const EventEngine<false> e = engine_of<false>(b, true, {0.9, 1e-2, false});
  WindowPlanner<false> planner(e);
  auto cuts_on = [&](std::size_t threads) {
    ThreadTeam team(threads);
    std::vector<std::size_t> coarse;
    const double lookahead = planner.choose(0.0, 2.0, team, coarse);  // velocities uniform in [-1, 1]
    std::vector<std::size_t> fine = coarse;
    planner.refine(0.0, 2.0, lookahead, team, fine);
    return std::pair{coarse, fine};
  };
  const auto [coarse, fine] = cuts_on(1);
  // This seed's random gaps at t = 0: 19 of the 64 fine candidates hold as long
  // as the coarse cut of the shortest bound, and 8 cuts become 27.
  EXPECT_EQ(coarse.size(), 8u);
  EXPECT_EQ(fine.size(), 27u);
  EXPECT_TRUE(std::is_sorted(fine.begin(), fine.end()));
  EXPECT_EQ(std::adjacent_find(fine.begin(), fine.end()), fine.end());
  for (std::size_t c : coarse) EXPECT_TRUE(std::binary_search(fine.begin(), fine.end(), c)) << "cut " << c;
  // Candidates are claimed by index: the same cuts on any team.
  EXPECT_EQ(cuts_on(3), cuts_on(1));
}

TEST(WindowPlanner, RefinedPlansGiveTheGlobalQueuesCollisionsOnARing) {
  expect_refined_windows_exact<false>(gas(20000), true, {0.9, 1e-2, false}, 300.0, 200000);
}

TEST(WindowPlanner, RefinedPlansGiveTheGlobalQueuesCollisionsOnALine) {
  expect_refined_windows_exact<false>(gas(12000), false, {1.0, 0.0, false}, 100.0, 120000);
}

// A ring of N = 1 mod 16 (its last block of slot times holds slot N - 1 alone):
// a bounce at the ring's end refreshes three blocks (EventTree, "refresh").
// Before, the windows stalled where the global queue ran on.
TEST(WindowPlanner, RefinedPlansGiveTheGlobalQueuesCollisionsOnARingOf4097) {
  expect_refined_windows_exact<false>(gas(4097), true, {0.9, 1e-2, false}, 20.0, 15000);
}

TEST(WindowPlanner, RefinedPlansGiveTheGlobalQueuesMerges) {
  // r = 0: every collision merges (the engine with links and masses), most bodies.
  expect_refined_windows_exact<true>(gas(12000), true, {0.0, 0.0, false}, 200.0, 6000);
}

TEST(WindowPlanner, RefinedPlansWithPistonsDrivenAtTheFineCandidates) {
  // Pistons 20 times faster than the gas drive shocks toward the fine candidates
  // near bodies 2560 and 5632 (coarse ones lie near multiples of 2048 here).
  Bodies b = gas(8192);
  for (std::size_t i = 2300; i < 2450; ++i) b.v[i] = 20.0;
  for (std::size_t i = 5750; i < 5900; ++i) b.v[i] = -20.0;
  expect_refined_windows_exact<false>(b, true, {0.9, 1e-2, false}, 6.0, 10 * b.size());
}

}  // namespace
}  // namespace shockgas::particles::detail
