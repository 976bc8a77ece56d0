// Every numeric scene key at the ends of what a user can type (finding 11 of a
// hostile pass: values beyond memory or the range of doubles gave the C++
// library's text, "vector::_M_default_append" or "map::at", instead of a
// message; the keys it named are tested one by one in test_hostile_values.cpp,
// this is the class). Each key of scene_schema() of kind integer or number is set, one
// at a time, to values far beyond any sensible range: the run refuses it with
// exit 2 naming the key, or takes it and runs (stopped at its first progress by
// SHOCKGAS_FAULT, or under a memory and CPU limit). Never a signal of its own,
// never a library's text.
#include <gtest/gtest.h>
#include <sys/resource.h>

#include <filesystem>
#include <string>
#include <vector>

#include "child_run.hpp"
#include "library_texts.hpp"
#include "run_dir_checks.hpp"
#include "shockgas/app/scene/scene_schema.hpp"

namespace shockgas::app {
namespace {

using namespace testing;

// Every table a key can be in, small enough to run in a moment.
const char* kEveryTable =
    "[scene]\nname = \"extremes\"\n[initial]\nN = 2000\n[particles]\nr = 0.5\ndelta = 1e-2\nt_end = 100\n"
    "[continuum]\nsolvers = [\"hopf_lax\"]\ncells = 2000\n[compare]\n[output]\nplots = false\n";

// Past 2^32, at the top of a 64-bit integer, negative; the ends of the doubles.
std::vector<std::string> extremes(const std::string& kind) {
  if (kind == "integer") return {"-1", "4e9", "9.2e18"};
  if (kind == "number") return {"1e308", "-1e308", "4.9e-324"};
  return {};
}

// A child that may take the value and run: stopped at its first progress
// report, and at 2 GiB of address space or 20 s of CPU if it never reports.
// AddressSanitizer reserves terabytes of address space: there its allocator
// refuses any block over 2 GiB instead (new throws std::bad_alloc).
Options bounded() {
#if defined(__SANITIZE_ADDRESS__)
  Options o =
      with_env({{"SHOCKGAS_FAULT", "compute:1"},
                {"ASAN_OPTIONS", "max_allocation_size_mb=2048:allocator_may_return_null=1:detect_leaks=0"}});
  o.in_child = [] {
    const rlimit cpu{20, 20};
    setrlimit(RLIMIT_CPU, &cpu);
  };
#else
  Options o = with_env({{"SHOCKGAS_FAULT", "compute:1"}});
  o.in_child = [] {
    const rlimit memory{2ul << 30, 2ul << 30}, cpu{20, 20};
    setrlimit(RLIMIT_AS, &memory);
    setrlimit(RLIMIT_CPU, &cpu);
  };
#endif
  return o;
}

TEST(KeysAtExtremes, EveryNumericKeyIsRefusedByNameOrRunsAndNoLibraryTextReachesTheUser) {
  const fs::path root = fresh_dir("keys-at-extremes");
  write_text(root / "scene.toml", kEveryTable);
  int cases = 0, refused = 0;
  for (const TableSpec& table : scene_schema())
    for (const KeySpec& key : table.keys)
      for (const std::string& value : extremes(key.info.kind)) {
        const std::string set = key.info.dotted() + "=" + value;
        Child child({"run", (root / "scene.toml").string(), "--out", (root / "out").string(), "-q", "--force",
                     "--set", set},
                    bounded());
        const int code = child.wait();
        const std::string err = child.err();
        ++cases;
        // refused: exit 2, naming the key as the user wrote it
        if (code == 2) {
          ++refused;
          EXPECT_NE(err.find("--set " + set + ": "), std::string::npos) << set << "\n" << err;
        } else {
          // taken: it ran until the fault stopped it, or to its end, or failed with a message
          EXPECT_TRUE(child.signal() == SIGKILL || code == 0 || code == 1) << set << ": " << code << "\n"
                                                                           << err;
          if (code == 1) {
            EXPECT_NE(err.find("shockgas: "), std::string::npos) << set << "\n" << err;
          }
        }
        expect_no_library_text(err, set + " gave library text");
      }
  EXPECT_GT(refused, 0);  // both ways were taken
  EXPECT_LT(refused, cases);
  std::cout << cases << " cases, " << refused << " refused\n";
}

}  // namespace
}  // namespace shockgas::app
