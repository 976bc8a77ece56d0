// A run killed with SIGKILL anywhere leaves one whole run, old or new, and the
// next run clears what it left (run_faults.hpp). The default set kills at five
// of the nine named points and at two random times; test_run_faults_slow.cpp
// (label slow) at all nine and six. The five are one of each kind of moment:
// computing, writing a staged file (result.h5 mid-way; the text files between
// it and the swap are staged by the same writer), the plotting process
// running, and either side of the swap (the last moment alpha holds, the first
// beta does). The two random times are the first two of the slow test's six.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "run_faults.hpp"

namespace shockgas::app {
namespace {

using namespace testing;

TEST(RunFaults, AKillAtAPointOfEachKindLeavesOneWholeRun) {
  const std::vector<std::string> chosen = {"compute", "write:result.h5:20", "plot:10", "swap", "swapped"};
  int checked = 0;
  for (const KillPoint& p : kEveryKillPoint) {
    if (std::find(chosen.begin(), chosen.end(), p.fault) == chosen.end()) continue;
    expect_one_whole_run_after_a_kill_at(p, "faults-" + std::to_string(checked++));
  }
  EXPECT_EQ(checked, static_cast<int>(chosen.size())) << "a chosen point is not among kEveryKillPoint";
}

TEST(RunFaults, AKillAtTwoRandomTimesLeavesOneWholeRun) {
  expect_one_whole_run_after_random_kills(2, "faults-random");
}

}  // namespace
}  // namespace shockgas::app
