// A damaged result file never crashes a reader (damaged_results.hpp): a short
// seeded run of every reader on a dozen damaged copies;
// test_damaged_results_slow.cpp runs many more.
#include "damaged_results.hpp"

namespace shockgas::app {
namespace {

using namespace testing;

TEST(DamagedResults, NoReaderCrashesOnADamagedFile) {
  DamagedResults cases;
  for (const ManifestKind kind : {ManifestKind::original, ManifestKind::recomputed, ManifestKind::removed})
    for (unsigned seed = 1; seed <= 4; ++seed) cases.check(seed, kind);
  cases.check_loads();
}

}  // namespace
}  // namespace shockgas::app
