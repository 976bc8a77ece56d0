// `shockgas tail` into its output directory (findings: an interrupt emptied
// the earlier study's files to their headers, a full disk left a CSV cut
// mid-number, and --out / or a run's directory was written into): the
// directory is checked as a run's, and replaced whole at each finished size.
#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "child_run.hpp"
#include "run_dir_checks.hpp"
#include "shockgas/app/directory/result_check.hpp"
#include "shockgas/app/files/manifest.hpp"

namespace shockgas::app {
namespace {

using namespace testing;

std::vector<std::string> tail_args(const fs::path& out, const std::string& sizes,
                                   const std::string& r = "0") {
  return {"tail",    "-q", "--N", sizes, "--realizations", "2",
          "--times", "10", "--r", r,     "--out",          out.string()};
}

// The study's rows of tail_runs.csv: one per (N, t).
std::size_t rows(const fs::path& dir) {
  std::ifstream in(dir / "tail_runs.csv");
  std::size_t n = 0;
  for (std::string line; std::getline(in, line);) ++n;
  return n - 1;
}

std::string differences(const fs::path& dir) {
  const auto manifest = read_manifest(dir);
  return manifest ? differences_of(check_listed_files(dir, *manifest, "")) : "no manifest";
}

TEST(TailRun, AnInterruptKeepsTheSizesFinishedEachFileWhole) {
  const fs::path out = fresh_dir("tail-interrupted") / "t";
  Child tail(tail_args(out, "1000,2000"), with_env({{"SHOCKGAS_FAULT", "published:1:stop"}}));
  ASSERT_TRUE(tail.wait_stopped()) << tail.err();
  kill(tail.pid(), SIGINT);
  kill(tail.pid(), SIGCONT);
  EXPECT_EQ(tail.wait(), 128 + SIGINT) << tail.err();
  EXPECT_NE(tail.err().find("the output directory is as the last finished size left it"), std::string::npos)
      << tail.err();
  EXPECT_EQ(differences(out), "");
  EXPECT_EQ(read_manifest(out)->scene, "tail");
  EXPECT_EQ(rows(out), 1u);  // N = 1000 at t = 10
  EXPECT_TRUE(leftovers(out).empty()) << leftovers(out).front();
}

TEST(TailRun, AnInterruptBeforeTheFirstSizeLeavesTheEarlierStudy) {
  const fs::path out = fresh_dir("tail-earlier") / "t";
  ASSERT_EQ(run_child(tail_args(out, "1000")).first, 0);
  const std::string before = read_text(out / "manifest.json");
  // Seconds of work before the first size is done: the interrupt comes first.
  Child tail({"tail", "-q", "--N", "100000", "--realizations", "6", "--times", "1e2,1e3", "--r", "0.5",
              "--out", out.string()});
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  kill(tail.pid(), SIGINT);
  EXPECT_EQ(tail.wait(), 128 + SIGINT) << tail.err();
  EXPECT_EQ(read_text(out / "manifest.json"), before);
  EXPECT_EQ(differences(out), "");
  EXPECT_TRUE(leftovers(out).empty()) << leftovers(out).front();
}

TEST(TailRun, TheOutputDirectoryIsCheckedAsARunsIs) {
  const fs::path root = fresh_dir("tail-target");
  const auto [code, err] = run_child(tail_args("/", "1000"));
  EXPECT_EQ(code, 2) << err;
  EXPECT_NE(err.find("a directory other than the root directory"), std::string::npos) << err;
  // A run's directory is another scene's results: refused unless forced, and
  // then replaced whole (no run file stays beside the study's).
  const fs::path run = root / "run";
  write_text(root / "scene.toml", "[initial]\nN = 100\n[particles]\nt_end = 1\n[output]\nplots = false\n");
  ASSERT_EQ(run_child({"run", (root / "scene.toml").string(), "--out", run.string(), "-q"}).first, 0);
  const auto [refused, said] = run_child(tail_args(run, "1000"));
  EXPECT_EQ(refused, 2) << said;
  EXPECT_NE(said.find("give --force"), std::string::npos) << said;
  EXPECT_TRUE(fs::exists(run / "result.h5"));
  std::vector<std::string> forced = tail_args(run, "1000");
  forced.push_back("--force");
  ASSERT_EQ(run_child(forced).first, 0);
  EXPECT_FALSE(fs::exists(run / "result.h5"));
  EXPECT_EQ(differences(run), "");
  EXPECT_EQ(read_manifest(run)->scene, "tail");
}

// A study an older version wrote (its three files, no manifest) is replaced
// as this scene's own results, as data/paper-runs/tail/ holds them.
TEST(TailRun, AnOlderStudyWithoutAManifestIsReplaced) {
  const fs::path out = fresh_dir("tail-older") / "t";
  for (const char* name : {"tail_phi.csv", "tail_windows.csv", "tail_runs.csv"})
    write_text(out / name, "N,t\n");
  ASSERT_EQ(run_child(tail_args(out, "1000")).first, 0);
  EXPECT_EQ(differences(out), "");
  EXPECT_EQ(rows(out), 1u);
}

}  // namespace
}  // namespace shockgas::app
