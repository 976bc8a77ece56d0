// run_indices: every index once on any number of threads, the first failure
// stops the handing out and is rethrown after the join.
#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <vector>

#include "shockgas/core/index_pool.hpp"

namespace shockgas {
namespace {

TEST(IndexPool, EveryIndexRunsOnceOnAnyNumberOfThreads) {
  for (const std::size_t threads : {1u, 2u, 3u, 8u, 100u}) {
    std::vector<std::atomic<int>> runs(37);
    run_indices(runs.size(), threads, [&](std::size_t k) { ++runs[k]; });
    for (std::size_t k = 0; k < runs.size(); ++k)
      EXPECT_EQ(runs[k].load(), 1) << "k = " << k << ", threads " << threads;
  }
}

TEST(IndexPool, NoIndicesRunNothing) {
  bool ran = false;
  run_indices(0, 4, [&](std::size_t) { ran = true; });
  EXPECT_FALSE(ran);
}

TEST(IndexPool, TheFirstFailureStopsFurtherIndicesAndIsRethrown) {
  // One thread: the order is 0, 1, 2, ...; index 5 throws, so 6.. never start.
  std::vector<int> runs(20, 0);
  EXPECT_THROW(run_indices(runs.size(), 1,
                           [&](std::size_t k) {
                             ++runs[k];
                             if (k == 5) throw std::runtime_error("job 5");
                           }),
               std::runtime_error);
  for (std::size_t k = 0; k < runs.size(); ++k) EXPECT_EQ(runs[k], k <= 5 ? 1 : 0) << "k = " << k;
}

TEST(IndexPool, AFailureOnAnotherThreadReachesTheCaller) {
  try {
    run_indices(1000, 3, [&](std::size_t k) {
      if (k == 3) throw std::invalid_argument("job 3");
    });
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "job 3");
  }
}

}  // namespace
}  // namespace shockgas
