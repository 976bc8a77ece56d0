// The cores "all cores" means: the affinity, capped by a container's quota.
#include <gtest/gtest.h>

#include <thread>

#include "shockgas/core/cores.hpp"

namespace shockgas {
namespace {

TEST(Cores, QuotaInWholeCores) {
  EXPECT_EQ(quota_cores("200000 100000"), 2u);    // cgroup v2 cpu.max: two cores
  EXPECT_EQ(quota_cores("150000 100000\n"), 1u);  // 1.5 cores: a second thread would be throttled
  EXPECT_EQ(quota_cores("50000 100000"), 1u);     // never below one
  EXPECT_EQ(quota_cores("max 100000"), std::nullopt);
  EXPECT_EQ(quota_cores("-1 100000"), std::nullopt);  // cgroup v1: no quota
  EXPECT_EQ(quota_cores(""), std::nullopt);           // no such file
}

TEST(Cores, UsableCoresWithinTheMachine) {
  const std::size_t cores = usable_cores();
  EXPECT_GE(cores, 1u);
  if (std::thread::hardware_concurrency() > 0) {
    EXPECT_LE(cores, std::thread::hardware_concurrency());
  }
}

}  // namespace
}  // namespace shockgas
