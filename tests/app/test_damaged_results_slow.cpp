// The longer run of test_damaged_results.cpp: 80 damaged copies of each kind.
#include "damaged_results.hpp"

namespace shockgas::app {
namespace {

using namespace testing;

TEST(DamagedResultsSlow, NoReaderCrashesOnManyDamagedFiles) {
  DamagedResults cases;
  for (const ManifestKind kind : {ManifestKind::original, ManifestKind::recomputed, ManifestKind::removed}) {
    for (unsigned seed = 100; seed < 180; ++seed) cases.check(seed, kind);
    cases.check_loads();
  }
}

}  // namespace
}  // namespace shockgas::app
