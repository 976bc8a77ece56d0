// The cuts of a window plan (particles/window_plan.hpp), refined: the candidates
// near every fine_bodies-th pair that surely stay open for the whole plan are
// added. Every cut must hold until the plan's horizon, or a collision across it
// would be missed: the windows with every plan refined give the global queue's
// collisions and final state to the bit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <vector>

#include "shockgas/core/initial_condition.hpp"
#include "window_scheduler.hpp"

namespace shockgas::particles::detail {
namespace {

using Engine = EventEngine<false>;

// A watch that never stops the run and never saves.
struct Unlimited {
  bool operator()(double, std::uint64_t) { return true; }
  std::uint64_t collisions_left(std::uint64_t) const { return std::numeric_limits<std::uint64_t>::max(); }
  bool tick(double) { return true; }
  bool saves_on_request() const { return false; }
  [[noreturn]] void save_and_stop(double) { std::abort(); }
};

Bodies gas(std::size_t n) {
  InitialParams ip;
  ip.N = n;
  ip.positions = Positions::random;
  ip.velocities = Velocities::uniform;
  ip.seed = 23;
  return make_initial_bodies(ip);
}

Engine engine_of(const Bodies& b, bool ring, const CollisionRule& rule) {
  return Engine(b.size(), static_cast<double>(b.size()), ring, rule,
                [&](std::size_t first, std::size_t count, double* x, double* v, double*) {
                  std::copy_n(b.x.begin() + first, count, x);
                  std::copy_n(b.v.begin() + first, count, v);
                });
}

struct Final {
  std::uint64_t collisions = 0;
  std::vector<double> x, v;
};

Final final_of(const Engine& e, double t) {
  Final f{e.collisions(), {}, {}};
  e.for_each_body(t, [&](std::size_t, double x, double v, double) { f.x.push_back(x), f.v.push_back(v); });
  return f;
}

// The global queue, and windows whose every plan is refined, from bodies b to t.
void expect_refined_windows_exact(const Bodies& b, bool ring, const CollisionRule& rule, double t,
                                  std::size_t threads) {
  Unlimited watch;
  Engine global = engine_of(b, ring, rule);
  global.use_global_queue();
  ASSERT_EQ(global.run_until(t, watch), EngineStop::reached);
  Engine windowed = engine_of(b, ring, rule);
  WindowScheduler<false> scheduler(windowed, threads, 0.0);
  ASSERT_EQ(scheduler.run_until(t, watch), EngineStop::reached);
  ASSERT_FALSE(scheduler.on_global_queue()) << scheduler.why_global();
  const Final a = final_of(global, t), w = final_of(windowed, t);
  ASSERT_GT(a.collisions, 10 * b.size());  // many plans
  EXPECT_EQ(w.collisions, a.collisions);
  EXPECT_EQ(w.x, a.x);
  EXPECT_EQ(w.v, a.v);
}

TEST(WindowPlanner, RefiningAddsCutsAndKeepsTheCoarseOnes) {
  const Bodies b = gas(1 << 15);
  const Engine e = engine_of(b, true, {0.9, 1e-2, false});
  WindowPlanner<false> planner(e);
  ThreadTeam team(1);
  std::vector<std::size_t> coarse;
  const double lookahead = planner.choose(0.0, 2.0, team, coarse);  // uniform velocities in [-1, 1]
  ASSERT_GT(lookahead, 0.0);
  std::vector<std::size_t> fine = coarse;
  planner.refine(0.0, 2.0, lookahead, team, fine);
  // Random gaps at t = 0: 19 of the 64 fine candidates hold as long as the
  // coarse cut of the shortest bound (8 cuts become 27).
  EXPECT_GT(fine.size(), 2 * coarse.size());
  EXPECT_TRUE(std::is_sorted(fine.begin(), fine.end()));
  EXPECT_EQ(std::adjacent_find(fine.begin(), fine.end()), fine.end());
  for (std::size_t c : coarse) EXPECT_TRUE(std::binary_search(fine.begin(), fine.end(), c)) << "cut " << c;
}

TEST(WindowPlanner, RefinedPlansGiveTheGlobalQueuesCollisionsOnARing) {
  expect_refined_windows_exact(gas(20000), true, {0.9, 1e-2, false}, 300.0, 1);
}

TEST(WindowPlanner, RefinedPlansGiveTheGlobalQueuesCollisionsOnALine) {
  expect_refined_windows_exact(gas(12000), false, {1.0, 0.0, false}, 100.0, 2);
}

TEST(WindowPlanner, FastBodiesDoNotCrossTheFineCuts) {
  // Pistons 20 times faster than the gas drive shocks toward the fine candidates
  // near bodies 2560 and 5632 (coarse ones lie near multiples of 2048 here): a
  // fine cut whose bound is shorter than the plan must not be taken.
  Bodies b = gas(8192);
  for (std::size_t i = 2300; i < 2450; ++i) b.v[i] = 20.0;
  for (std::size_t i = 5750; i < 5900; ++i) b.v[i] = -20.0;
  expect_refined_windows_exact(b, true, {0.9, 1e-2, false}, 6.0, 1);
}

}  // namespace
}  // namespace shockgas::particles::detail
