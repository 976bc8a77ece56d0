// The whole of run_faults.hpp (label slow): a kill at each of the nine named
// points and at six random times, about 40 CPU-seconds of runs of the command;
// test_run_faults.cpp kills at five of the points and two of the times.
#include <gtest/gtest.h>

#include <string>

#include "run_faults.hpp"

namespace shockgas::app {
namespace {

using namespace testing;

TEST(RunFaultsSlow, AKillAtEachNamedPointLeavesOneWholeRun) {
  for (std::size_t i = 0; i < kEveryKillPoint.size(); ++i)
    expect_one_whole_run_after_a_kill_at(kEveryKillPoint[i], "faults-slow-" + std::to_string(i));
}

TEST(RunFaultsSlow, AKillAtSixRandomTimesLeavesOneWholeRun) {
  expect_one_whole_run_after_random_kills(6, "faults-slow-random");
}

}  // namespace
}  // namespace shockgas::app
