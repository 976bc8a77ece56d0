// The command end to end: exit codes, nothing written on bad input, a complete
// result file with provenance on success.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "run_command.hpp"
#include "run_comparison.hpp"
#include "shockgas/app/cli/info.hpp"
#include "shockgas/app/output/hdf5_file.hpp"

namespace shockgas::app {
namespace {

namespace fs = std::filesystem;

using testing_support::run;

fs::path temp_dir(const std::string& name) {
  fs::path dir = testing_support::process_temp_path("shockgas-test-", name);
  fs::remove_all(dir);
  return dir;
}

fs::path write_scene(const fs::path& dir, const std::string& text) {
  fs::create_directories(dir);
  fs::path path = dir / "scene.toml";
  std::ofstream(path) << text;
  return path;
}

const char* kSmallScene =
    "[initial]\nN = 200\n[particles]\nr = 0.5\ndelta = 1e-2\nt_end = 20\nsamples = 8\n"
    "[continuum]\nsolvers = [\"hopf_lax\", \"godunov\"]\ncells = 200\n[compare]\n[output]\nplots = false\n";

TEST(Command, BadSceneExitsTwoAndWritesNothing) {
  const fs::path dir = temp_dir("bad");
  const fs::path scene = write_scene(dir, "[particles]\nr = 2\n");
  const fs::path out = dir / "out";
  EXPECT_EQ(run({"run", scene.string(), "--out", out.string(), "-q"}), 2);
  EXPECT_FALSE(fs::exists(out));
}

TEST(Command, BadOverrideExitsTwoAndWritesNothing) {
  const fs::path dir = temp_dir("badset");
  const fs::path scene = write_scene(dir, kSmallScene);
  const fs::path out = dir / "out";
  EXPECT_EQ(run({"run", scene.string(), "--out", out.string(), "--set", "particles.nope=1"}), 2);
  EXPECT_FALSE(fs::exists(out));
}

TEST(Command, BadTailOptionsExitTwoAndWriteNothing) {
  const fs::path out = temp_dir("tail") / "out";
  EXPECT_EQ(run({"tail", "--realizations", "1", "--out", out.string(), "-q"}), 2);
  EXPECT_EQ(run({"tail", "--N", "1500.5", "--out", out.string(), "-q"}), 2);
  EXPECT_EQ(run({"tail", "--times", "1e3,1e2", "--out", out.string(), "-q"}), 2);
  EXPECT_FALSE(fs::exists(out));
}

TEST(Command, SolverLimitIsCheckedBeforeAnyWork) {
  const fs::path dir = temp_dir("preflight");
  const fs::path scene = write_scene(dir, kSmallScene);
  const fs::path out = dir / "out";
  // MUSCL-Hancock with the mc limiter is stable only up to CFL 0.85 (godunov_scheme.hpp).
  EXPECT_EQ(run({"run", scene.string(), "--out", out.string(), "-q", "--set",
                 "continuum.solvers=[\"godunov2\"]", "--set", "continuum.cfl=0.95"}),
            2);
  EXPECT_FALSE(fs::exists(out));
}

TEST(Command, ScheduleIsCheckedBeforeAnyWork) {
  const fs::path dir = temp_dir("schedule");
  const fs::path scene = write_scene(dir, kSmallScene);
  const fs::path out = dir / "out";
  // Sticky sub-threshold merges with r > 0 bounce unequal masses: the time windows do not apply
  // (window_plan.hpp, window_obstacle).
  EXPECT_EQ(
      run({"run", scene.string(), "--out", out.string(), "-q", "--set", "particles.schedule=\"windows\"",
           "--set", "initial.N=2048", "--set", "particles.subthreshold=\"sticky\""}),
      2);
  EXPECT_FALSE(fs::exists(out));
  // The same with r = 0.5 runs.
  EXPECT_EQ(run({"run", scene.string(), "--out", out.string(), "-q", "--set",
                 "particles.schedule=\"windows\"", "--set", "initial.N=2048", "--set", "particles.t_end=2"}),
            0);
  EXPECT_TRUE(fs::exists(out / "summary.json"));
}

TEST(Command, MissingSceneFileExitsTwo) { EXPECT_EQ(run({"run", "/nonexistent/scene.toml", "-q"}), 2); }

TEST(Command, UnknownSubcommandOrOptionExitsTwo) {
  EXPECT_EQ(run({"frobnicate"}), 2);
  EXPECT_EQ(run({"run", "x.toml", "--bogus"}), 2);
}

TEST(Command, HelpAndVersionExitZero) {
  EXPECT_EQ(run({"--help"}), 0);
  EXPECT_EQ(run({"--version"}), 0);
  EXPECT_EQ(run({"scene", "--defaults"}), 0);
}

TEST(Command, RunWritesCompleteResultWithProvenance) {
  const fs::path dir = temp_dir("run");
  const fs::path scene = write_scene(dir, kSmallScene);
  const fs::path out = dir / "out";
  ASSERT_EQ(run({"run", scene.string(), "--out", out.string(), "-q", "--set", "particles.r=0.25"}), 0);
  for (const char* f : {"result.h5", "summary.json", "report.md"}) EXPECT_TRUE(fs::exists(out / f)) << f;
  for (const auto& entry : fs::directory_iterator(out))
    EXPECT_EQ(entry.path().string().find(".partial"), std::string::npos) << entry.path();

  const Hdf5File h5 = Hdf5File::open((out / "result.h5").string());
  std::vector<std::string> names;
  for (const auto& d : h5.datasets()) {
    names.push_back(d.path);
    EXPECT_FALSE(d.unit.empty()) << d.path << " has no unit";
  }
  for (const char* needed : {"/particles/t", "/particles/T", "/particles/n_bodies", "/particles/collisions",
                             "/particles/final/x", "/particles/final/v", "/particles/final/m",
                             "/continuum/godunov/v", "/continuum/hopf_lax/shocks/x", "/compare/clusters_x"})
    EXPECT_NE(std::find(names.begin(), names.end(), needed), names.end()) << needed;
  bool has_commit = false, has_override = false;
  for (const auto& [name, value] : h5.attributes("/")) {
    has_commit |= name == "git_commit" && !value.empty();
    has_override |= name == "overrides" && value == "--set particles.r=0.25";
  }
  EXPECT_TRUE(has_commit);
  EXPECT_TRUE(has_override);
  const std::string info = describe_result((out / "result.h5").string());
  EXPECT_NE(info.find("/particles/T"), std::string::npos);
  EXPECT_NE(info.find("shockgas_version"), std::string::npos);
}

TEST(Command, InfoOnMissingFileExitsTwo) { EXPECT_EQ(run({"info", "/nonexistent/result.h5"}), 2); }

// The jackknife error of T_exponent stands beside the exponent it is the error
// of (found: written, from a two-point slope, when the window held too few
// samples for T_exponent itself).
TEST(Command, TheExponentsJackknifeErrorComesWithTheExponent) {
  const fs::path dir = temp_dir("jackknife");
  const fs::path scene =
      write_scene(dir,
                  "[initial]\nN = 2000\n[particles]\nr = 0.5\nt_end = 1e3\nrealizations = 3\n[compare]\n"
                  "[output]\nplots = false\n");
  for (const int samples : {5, 40}) {  // 2 and 16 samples in [t_end / 10, t_end]
    const fs::path out = dir / ("out" + std::to_string(samples));
    ASSERT_EQ(run({"run", scene.string(), "--out", out.string(), "-q", "--set",
                   "particles.samples=" + std::to_string(samples)}),
              0);
    const auto analysis = testing::read_json(out / "summary.json")["analysis"];
    EXPECT_EQ(analysis.contains("T_exponent"), samples == 40);
    EXPECT_EQ(analysis.contains("T_exponent_jackknife_error"), samples == 40);
  }
}

}  // namespace
}  // namespace shockgas::app
