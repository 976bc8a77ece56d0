// A fixed team of threads (core/thread_team.hpp): every member runs every
// stage once, the caller returns only when all have, and a member's exception
// reaches the caller; stages in quick succession (the members spinning between
// them) and far apart (the members asleep) alike.
#include <gtest/gtest.h>

#include <chrono>
#include <stdexcept>
#include <thread>
#include <vector>

#include "shockgas/core/thread_team.hpp"

namespace shockgas {
namespace {

TEST(ThreadTeam, EveryMemberRunsEveryStageBeforeTheCallerGoesOn) {
  for (std::size_t size : {1u, 2u, 3u}) {
    ThreadTeam team(size);
    ASSERT_EQ(team.size(), size);
    std::vector<long> runs(size, 0);
    for (int stage = 0; stage < 5000; ++stage) {
      team.run([&](std::size_t k) { ++runs[k]; });
      // Each member's count is this stage's when run() returns: nobody runs behind.
      for (std::size_t k = 0; k < size; ++k) ASSERT_EQ(runs[k], stage + 1) << "member " << k;
    }
  }
}

TEST(ThreadTeam, MembersAsleepBetweenStagesWakeForTheNext) {
  ThreadTeam team(2);
  std::vector<int> runs(2, 0);
  for (int stage = 0; stage < 3; ++stage) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));  // past any spin: the members sleep
    team.run([&](std::size_t k) { ++runs[k]; });
  }
  EXPECT_EQ(runs, (std::vector<int>{3, 3}));
}

TEST(ThreadTeam, AMembersExceptionReachesTheCallerAndTheTeamGoesOn) {
  ThreadTeam team(2);
  EXPECT_THROW(team.run([](std::size_t k) {
    if (k == 1) throw std::runtime_error("member 1");
  }),
               std::runtime_error);
  int ran = 0;
  team.run([&](std::size_t k) {
    if (k == 0) ++ran;
  });
  EXPECT_EQ(ran, 1);
}

}  // namespace
}  // namespace shockgas
