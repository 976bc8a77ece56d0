// The pool's wait (realization_pool.hpp): a poll that wakes on each ended
// realization and ended worker, not on a clock, and says whether it woke on news.
#include <gtest/gtest.h>

#include <chrono>
#include <memory>

#include "shockgas/app/ensemble/realization_pool.hpp"
#include "shockgas/app/input/scene_parser.hpp"

namespace shockgas::app {
namespace {

TEST(RealizationPool, WaitWakesOnTheRealizationsThatEndAndOnNothingElse) {
  const Scene scene = parse_scene(
      "[initial]\nN = 2000\n[particles]\nr = 0.9\ndelta = 1e-2\nt_end = 20\nrealizations = 3\nthreads = 1\n",
      "pool.toml");
  const auto plan = std::make_shared<const EnsemblePlan>(scene, std::nullopt, std::nullopt);
  RealizationPool pool(plan, plan->items(), 1, false);
  std::size_t records = 0;
  int woken = 0;
  // A bound no realization of 2000 bodies comes near: each wait ends on news.
  constexpr auto kBound = std::chrono::minutes(2);
  do {
    ASSERT_TRUE(pool.wait(kBound));
    ++woken;
    records += pool.take_finished().size();
  } while (!pool.finished());
  records += pool.take_finished().size();
  pool.wait(std::chrono::milliseconds(0));  // the worker's end, should finished() have seen it first
  ASSERT_FALSE(pool.failure());
  EXPECT_EQ(records, 3u);
  EXPECT_GE(woken, 1);
  EXPECT_LE(woken, 4);                                    // 3 realizations and 1 worker: at most as many news
  EXPECT_FALSE(pool.wait(std::chrono::milliseconds(1)));  // nothing ends after the end
}

}  // namespace
}  // namespace shockgas::app
