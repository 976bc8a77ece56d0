// `shockgas bench` as a whole (shockgas/app/cli/bench_run.cpp): its directory is staged and
// committed with a manifest, as a run's is (the full disk:
// test_full_disk.cpp), and a bench of some sections re-measures those without
// losing the others' tables (finding: the staged directory held only the
// sections measured, and replaced the earlier bench whole).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "child_run.hpp"
#include "run_dir_checks.hpp"
#include "shockgas/app/files/manifest.hpp"

namespace shockgas::app {
namespace {

using namespace testing;

TEST(BenchRun, ASectionMeasuredAgainKeepsTheOtherSectionsTables) {
  if (std::system("/usr/bin/python3 -c 'import matplotlib' 2>/dev/null") != 0)
    GTEST_SKIP() << "/usr/bin/python3 lacks matplotlib";
  const fs::path out = fresh_dir("bench-sections") / "bench";
  auto bench = [&](const std::string& section) {
    return run_child({"bench", "-q", "--out", out.string()},
                     with_env({{"SHOCKGAS_BENCH_SECTIONS", section}}));
  };
  const auto [first, why_first] = bench("continuum_stability");
  ASSERT_EQ(first, 0) << why_first;
  const std::string cfl_before = read_text(out / "stability_cfl.csv");
  auto failures_of = [&](const std::string& section) {  // rows of failures.csv found in that section
    std::size_t n = 0;
    std::istringstream in(read_text(out / "failures.csv"));
    for (std::string line; std::getline(in, line);) n += line.rfind(section + ",", 0) == 0;
    return n;
  };
  const std::size_t stability_failures = failures_of("continuum_stability");
  ASSERT_GT(stability_failures, 0u) << "no failure rows: their keeping would go unchecked";
  // The second section is the cheapest other one (particles_wp, about 6 CPU-seconds;
  // particles_stability takes 13): which one it is does not matter to what is kept.
  const auto [second, why_second] = bench("particles_wp");
  ASSERT_EQ(second, 0) << why_second;
  EXPECT_EQ(read_text(out / "stability_cfl.csv"), cfl_before);        // kept, not measured again
  EXPECT_EQ(failures_of("continuum_stability"), stability_failures);  // and its failures with it
  const std::optional<Manifest> m = read_manifest(out);
  ASSERT_TRUE(m.has_value());
  EXPECT_EQ(m->scene, "bench");
  for (const std::string file :
       {"stability_cfl.csv", "stability_cfl.png", "particles_cost.csv", "particles_cost.png"})
    EXPECT_NE(m->find(file), nullptr) << file;
  const auto [checked, said] = run_child({"info", out.string()});
  EXPECT_EQ(checked, 0) << said;

  // Nothing unchecked is carried: a damaged earlier table stops a bench of
  // some sections before any work, naming it.
  { std::ofstream(out / "stability_cfl.csv", std::ios::app) << "junk\n"; }
  const auto [refused, why] = bench("particles_wp");
  EXPECT_EQ(refused, 2) << why;
  EXPECT_NE(why.find("stability_cfl.csv damaged"), std::string::npos) << why;
}

// A section that does not exist is refused before anything is made (finding:
// it measured nothing, exit 0, and emptied the failure table).
TEST(BenchRun, ASectionThatDoesNotExistIsRefused) {
  const fs::path out = fresh_dir("bench-no-section") / "bench";
  for (const std::string list : {"bogus", ",", "CONTINUUM_STABILITY"}) {
    const auto [code, err] =
        run_child({"bench", "-q", "--out", out.string()}, with_env({{"SHOCKGAS_BENCH_SECTIONS", list}}));
    EXPECT_EQ(code, 2) << list << "\n" << err;
    EXPECT_NE(err.find("SHOCKGAS_BENCH_SECTIONS = \"" + list + "\" is not allowed"), std::string::npos)
        << err;
    EXPECT_FALSE(fs::exists(out));
  }
}

// --out with a trailing "/" names the same directory (finding: the bench put its
// lock, "..lock", inside it and then refused it as holding a file no run wrote).
TEST(BenchRun, AnOutputDirectoryWithATrailingSlashIsThatDirectory) {
  if (std::system("/usr/bin/python3 -c 'import matplotlib' 2>/dev/null") != 0)
    GTEST_SKIP() << "/usr/bin/python3 lacks matplotlib";
  const fs::path out = fresh_dir("bench-slash") / "bench";
  const auto [code, err] = run_child({"bench", "-q", "--out", out.string() + "/"},
                                     with_env({{"SHOCKGAS_BENCH_SECTIONS", "continuum_stability"}}));
  ASSERT_EQ(code, 0) << err;
  EXPECT_FALSE(fs::exists(out / "..lock"));
  EXPECT_EQ(run_child({"info", out.string()}).first, 0);
}

}  // namespace
}  // namespace shockgas::app
