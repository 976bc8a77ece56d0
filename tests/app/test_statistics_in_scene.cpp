// A scene with [statistics] (shockgas/app/run/stage_statistics.cpp): its run
// writes the shock statistics of its realizations, the same numbers, byte for
// byte, as `shockgas stats` on that run; a merged run writes those of all its
// realizations, a shard none; a scene that cannot give them is refused before
// any work, naming the key.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "child_run.hpp"
#include "run_dir_checks.hpp"

namespace shockgas::app {
namespace {

namespace fs = std::filesystem;
using namespace testing;

// The exact sticky gas from white noise, 6 realizations of N = 4000 at t = 300.
const char* kScene =
    "[scene]\nname = \"in-scene\"\n[initial]\nN = 4000\nvelocities = \"uniform\"\nseed = 5\n"
    "[particles]\nr = 0\nsolver = \"hull\"\nt_end = 300\nsamples = 4\nrealizations = 6\n[statistics]\n";

std::pair<int, std::string> run_scene(const fs::path& scene, const fs::path& out,
                                      std::vector<std::string> more = {}) {
  std::vector<std::string> args = {"run", scene.string(), "--out", out.string(), "-q", "--no-plots"};
  args.insert(args.end(), more.begin(), more.end());
  return run_child(args);
}

TEST(StatisticsInScene, ARunWritesTheStatisticsTheCommandGives) {
  const fs::path root = fresh_dir("statistics-in-scene");
  write_text(root / "s.toml", kScene);
  // With its plots: the statistics page is drawn by the run's plotting process.
  ASSERT_EQ(run_child({"run", (root / "s.toml").string(), "--out", (root / "run").string(), "-q"}).first, 0);
  for (const char* name : {"statistics.csv", "statistics.md", "statistics.h5", "statistics.png"})
    EXPECT_TRUE(fs::is_regular_file(root / "run" / name)) << name;
  ASSERT_EQ(
      run_child({"stats", (root / "run").string(), "--out", (root / "cmd").string(), "-q", "--no-plots"})
          .first,
      0);
  EXPECT_EQ(read_text(root / "run" / "statistics.csv"), read_text(root / "cmd" / "statistics.csv"));
  EXPECT_EQ(read_text(root / "run" / "statistics.md"), read_text(root / "cmd" / "statistics.md"));
  const std::string report = read_text(root / "run" / "report.md");
  EXPECT_NE(report.find("writing result.h5, summary.json, statistics.h5, .csv, .md"), std::string::npos)
      << report;
  EXPECT_NE(report.find("## Shock statistics over the realizations"), std::string::npos) << report;
  EXPECT_NE(report.find("6 realizations at t = 300"), std::string::npos) << report;
  // The manifest vouches for the new files too.
  EXPECT_EQ(run_child({"info", (root / "run").string()}).first, 0);
}

TEST(StatisticsInScene, AMergedRunWritesThemAndAShardDoesNot) {
  const fs::path root = fresh_dir("statistics-in-scene-shards");
  write_text(root / "s.toml", kScene);
  ASSERT_EQ(run_scene(root / "s.toml", root / "whole").first, 0);
  ASSERT_EQ(run_scene(root / "s.toml", root / "a", {"--realizations", "0:2"}).first, 0);
  ASSERT_EQ(run_scene(root / "s.toml", root / "b", {"--realizations", "2:6"}).first, 0);
  EXPECT_FALSE(fs::exists(root / "a" / "statistics.csv"));
  ASSERT_EQ(run_child({"merge", (root / "a").string(), (root / "b").string(), "--out",
                       (root / "merged").string(), "-q", "--no-plots"})
                .first,
            0);
  EXPECT_EQ(read_text(root / "merged" / "statistics.csv"), read_text(root / "whole" / "statistics.csv"));
}

// Every realization stopped by a limit: the run keeps its results and says why
// there are no statistics, and writes none.
TEST(StatisticsInScene, WithoutARealizationAtTEndTheRunSaysSoAndWritesNone) {
  const fs::path root = fresh_dir("statistics-in-scene-stopped");
  write_text(root / "s.toml", kScene);
  ASSERT_EQ(run_scene(root / "s.toml", root / "run",
                      {"--set", "particles.solver=events", "--set", "particles.max_collisions=100"})
                .first,
            0);
  EXPECT_FALSE(fs::exists(root / "run" / "statistics.csv"));
  const std::string report = read_text(root / "run" / "report.md");
  EXPECT_NE(report.find("None: no realization reached particles.t_end = 300"), std::string::npos) << report;
}

TEST(StatisticsInScene, ASceneThatCannotGiveThemIsRefusedNamingTheKey) {
  const fs::path root = fresh_dir("statistics-in-scene-refused");
  write_text(root / "s.toml", kScene);
  const auto [never, said] =
      run_scene(root / "s.toml", root / "never", {"--set", "particles.final_clusters=never"});
  EXPECT_EQ(never, 2);
  EXPECT_NE(said.find("particles.final_clusters"), std::string::npos) << said;
  EXPECT_NE(said.find("[statistics]"), std::string::npos) << said;
  EXPECT_FALSE(fs::exists(root / "never"));

  write_text(root / "c.toml",
             "[initial]\nN = 64\nvelocities = \"expression\"\nv0 = \"sin(2*pi*x)\"\n"
             "[continuum]\nt_end = 1\nsolvers = [\"hopf_lax\"]\n[statistics]\n");
  const auto [alone, why] = run_scene(root / "c.toml", root / "alone");
  EXPECT_EQ(alone, 2);
  EXPECT_NE(why.find("[statistics] only together with [particles]"), std::string::npos) << why;
}

}  // namespace
}  // namespace shockgas::app
