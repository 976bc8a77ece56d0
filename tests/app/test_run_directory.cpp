// The run directory is whole or absent (findings: a failed run mixed old and
// new results; another scene's results were overwritten without a word and its
// stale plots kept; killed runs left files no run cleared): replaced as a
// whole, refused when it holds what a run must not replace, locked, and cleared
// of what killed runs left.
#include <grp.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "child_run.hpp"
#include "run_dir_checks.hpp"
#include "shockgas/app/cli/command.hpp"
#include "shockgas/app/directory/run_directory.hpp"
#include "shockgas/app/directory/run_target.hpp"

namespace shockgas::app {
namespace {

using namespace testing;

int run(std::vector<std::string> args, std::string* err = nullptr) {
  args.insert(args.begin(), "shockgas");
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  ::testing::internal::CaptureStderr();
  const int code = run_command(static_cast<int>(argv.size()), argv.data());
  const std::string text = ::testing::internal::GetCapturedStderr();
  if (err) *err = text;
  return code;
}

struct Dirs {
  fs::path root, a, b, out;
};

Dirs setup(const std::string& name) {
  Dirs d;
  d.root = fresh_dir(name);
  d.a = d.root / "alpha.toml";
  d.b = d.root / "beta.toml";
  write_text(d.a, kSceneA);
  write_text(d.b, kSceneB);
  d.out = d.root / "results";
  return d;
}

TEST(RunDirectory, ASceneRunAgainReplacesItsResultsAsAWhole) {
  const Dirs d = setup("rundir-again");
  ASSERT_EQ(run({"run", d.a.string(), "--out", d.out.string(), "-q", "--no-plots"}), 0);
  EXPECT_EQ(whole_run(d.out, "alpha"), "");
  ASSERT_EQ(
      run({"run", d.a.string(), "--out", d.out.string(), "-q", "--no-plots", "--set", "particles.r=0.3"}), 0);
  EXPECT_EQ(whole_run(d.out, "alpha"), "");
  EXPECT_NE(read_text(d.out / "summary.json").find("particles.r=0.3"), std::string::npos);
  EXPECT_TRUE(leftovers(d.out).empty()) << leftovers(d.out).front();
}

TEST(RunDirectory, AnotherScenesResultsAreRefusedUnlessForced) {
  const Dirs d = setup("rundir-other");
  const fs::path script = fake_plot_script(d.root, 0);
  setenv("SHOCKGAS_PLOT_SCRIPT", script.c_str(), 1);
  ASSERT_EQ(run({"run", d.a.string(), "--out", d.out.string(), "-q"}), 0);
  ASSERT_TRUE(fs::exists(d.out / "alpha.png"));
  std::string err;
  EXPECT_EQ(run({"run", d.b.string(), "--out", d.out.string(), "-q"}, &err), 2);
  EXPECT_NE(err.find("the results of scene \"alpha\""), std::string::npos) << err;
  EXPECT_NE(err.find("--force"), std::string::npos) << err;
  EXPECT_EQ(whole_run(d.out, "alpha"), "");
  // Forced, the old results go as a whole: no stale picture of alpha beside beta's.
  EXPECT_EQ(run({"run", d.b.string(), "--out", d.out.string(), "-q", "--force"}), 0);
  unsetenv("SHOCKGAS_PLOT_SCRIPT");
  EXPECT_EQ(whole_run(d.out, "beta"), "");
  EXPECT_TRUE(fs::exists(d.out / "beta.png"));
  EXPECT_FALSE(fs::exists(d.out / "alpha.png"));
}

TEST(RunDirectory, FilesARunDidNotWriteAreNeverReplaced) {
  const Dirs d = setup("rundir-foreign");
  write_text(d.out / "notes.txt", "my notes\n");
  std::string err;
  EXPECT_EQ(run({"run", d.a.string(), "--out", d.out.string(), "-q", "--force"}, &err), 2);
  EXPECT_NE(err.find("notes.txt"), std::string::npos) << err;
  EXPECT_EQ(read_text(d.out / "notes.txt"), "my notes\n");
  // The same inside a run directory: a file its manifest does not list.
  ASSERT_EQ(run({"run", d.a.string(), "--out", (d.root / "r2").string(), "-q", "--no-plots"}), 0);
  write_text(d.root / "r2" / "mine.dat", "1 2 3\n");
  EXPECT_EQ(run({"run", d.a.string(), "--out", (d.root / "r2").string(), "-q", "--no-plots"}, &err), 2);
  EXPECT_NE(err.find("mine.dat"), std::string::npos) << err;
}

TEST(RunDirectory, TheRootHomeSourceAndCurrentDirectoriesAreRefused) {
  const Dirs d = setup("rundir-protected");
  const fs::path cwd = fs::current_path();
  std::vector<std::string> refused = {".",
                                      "/",
                                      SHOCKGAS_SOURCE_DIR,
                                      cwd.parent_path().string(),
                                      "..",
                                      std::string(SHOCKGAS_SOURCE_DIR) + "/.."};
  if (const char* home = std::getenv("HOME")) refused.push_back(home);
  for (const auto& out : refused) {
    std::string err;
    EXPECT_EQ(run({"run", d.a.string(), "--out", out, "-q", "--no-plots", "--force"}, &err), 2) << out;
    EXPECT_NE(err.find("--out"), std::string::npos) << err;
  }
  EXPECT_TRUE(fs::exists(fs::path(SHOCKGAS_SOURCE_DIR) / "CMakeLists.txt"));
}

TEST(RunDirectory, AFileIsNotAnOutputDirectory) {
  const Dirs d = setup("rundir-file");
  write_text(d.out, "a file\n");
  EXPECT_EQ(run({"run", d.a.string(), "--out", d.out.string(), "-q", "--no-plots"}), 2);
  EXPECT_EQ(read_text(d.out), "a file\n");
}

// Run as another user (nobody) in a world-writable directory with the sticky
// bit, as /tmp or a shared scratch disk: a directory someone else owns there
// cannot be moved aside (rename(2) fails with EPERM), so it is refused before
// the run, not after it has computed everything; a directory of its own is
// replaced. (Found: the run computed, then failed to exchange the directories.)
TEST(RunDirectory, AnotherUsersDirectoryInAStickyDirectoryIsRefusedBeforeTheRun) {
  if (::geteuid() != 0) GTEST_SKIP() << "runs the command as another user, which needs root";
  constexpr uid_t nobody = 65534;
  const Dirs d = setup("rundir-sticky");
  fs::permissions(d.root, fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec |
                              fs::perms::others_read | fs::perms::others_exec);
  const fs::path shared = d.root / "shared", theirs = shared / "theirs", own = shared / "own";
  fs::create_directories(theirs);
  fs::create_directories(own);
  fs::permissions(shared, fs::perms::all | fs::perms::sticky_bit);
  fs::permissions(theirs, fs::perms::all);  // writable by all, but root's
  ASSERT_EQ(::chown(own.c_str(), nobody, nobody), 0);
  testing::Options as_nobody;
  as_nobody.in_child = [] {
    if (::setgroups(0, nullptr) != 0 || ::setresgid(nobody, nobody, nobody) != 0 ||
        ::setresuid(nobody, nobody, nobody) != 0)
      _exit(125);
  };
  const auto [refused, why] =
      testing::run_child({"run", d.a.string(), "--out", theirs.string(), "-q", "--no-plots"}, as_nobody);
  EXPECT_EQ(refused, 2) << why;
  EXPECT_NE(why.find("sticky bit"), std::string::npos) << why;
  EXPECT_EQ(why.find("run failed"), std::string::npos) << why;
  EXPECT_TRUE(fs::is_empty(theirs));
  EXPECT_EQ(std::distance(fs::directory_iterator(shared), fs::directory_iterator()), 2);  // nothing left
  const auto [replaced, said] =
      testing::run_child({"run", d.a.string(), "--out", own.string(), "-q", "--no-plots"}, as_nobody);
  EXPECT_EQ(replaced, 0) << said;
  EXPECT_EQ(whole_run(own, "alpha"), "");
}

TEST(RunDirectory, ALockKeepsASecondRunOut) {
  const Dirs d = setup("rundir-lock");
  const fs::path target = fs::weakly_canonical(d.out);
  std::string err;
  {
    const DirectoryLock held(target, d.out.string());
    EXPECT_EQ(run({"run", d.a.string(), "--out", d.out.string(), "-q", "--no-plots"}, &err), 2);
    EXPECT_NE(err.find("no other run is writing"), std::string::npos) << err;
    EXPECT_FALSE(fs::exists(d.out));
  }
  EXPECT_EQ(run({"run", d.a.string(), "--out", d.out.string(), "-q", "--no-plots"}), 0);
  EXPECT_TRUE(leftovers(d.out).empty());
}

// In an MPI job every rank checks the output directory while rank 0 may
// already write its checkpoint through a temporary file and rename it (the
// finding: rank 1 failed the job with "cannot make canonical path" for a
// checkpoint.bin.partial-PID that was gone by the time it was resolved). A race:
// without the fix it failed 2 runs in 3 at 3000 checks, more often at 10000.
TEST(RunDirectory, AFileRenamedWhileTheDirectoryIsCheckedDoesNotFailTheCheck) {
  const Dirs d = setup("rundir-vanishing");
  fs::create_directories(d.out);
  std::atomic<bool> done{false};
  std::thread writer([&] {
    const fs::path partial = d.out / "checkpoint.bin.partial-4242";
    while (!done) {
      std::ofstream(partial) << "a checkpoint being written";
      std::error_code ec;
      fs::rename(partial, d.out / "checkpoint.bin", ec);
    }
  });
  int failures = 0;
  std::string first;
  for (int i = 0; i < 10000; ++i) try {
      check_target_contents(d.out, d.out.string(), "alpha", /*force=*/true);
    } catch (const std::exception& e) {
      if (failures++ == 0) first = e.what();
    }
  done = true;
  writer.join();
  EXPECT_EQ(failures, 0) << first;
}

TEST(RunDirectory, AFailureNamesTheFileInTheTargetNotInTheStagingDirectory) {
  const Dirs d = setup("rundir-message");
  RunDirectory dir(d.out, "alpha", false);
  const std::string message = "H5Fcreate failed on " + (dir.staging() / "v1" / "result.h5").string() +
                              " (No space left on device); cannot write " +
                              (dir.staging() / "a.png").string();
  const std::string target = fs::weakly_canonical(d.out).string();
  EXPECT_EQ(with_staging_as_target(message), "H5Fcreate failed on " + target +
                                                 "/v1/result.h5 (No space left on device); cannot write " +
                                                 target + "/a.png");
  EXPECT_EQ(with_staging_as_target("cannot write /x/.run.tmp-12/result.h5"),
            "cannot write /x/.run.tmp-12/result.h5");
  // the staging directory itself (a failed exchange) keeps its name
  const std::string exchange =
      "cannot exchange " + dir.staging().string() + " and " + target + ": Invalid argument";
  EXPECT_EQ(with_staging_as_target(exchange), exchange);
}

TEST(RunDirectory, WhatKilledRunsLeftIsClearedByTheNextRun) {
  const Dirs d = setup("rundir-leftovers");
  ASSERT_EQ(run({"run", d.a.string(), "--out", d.out.string(), "-q", "--no-plots"}), 0);
  write_text(d.root / ".results.tmp-4242-abcdef" / "result.h5", "half a file");
  write_text(d.out.parent_path() / ".results.lock", "4242");  // a lock file whose holder is gone
  std::string err;
  ASSERT_EQ(run({"run", d.a.string(), "--out", d.out.string(), "-q", "--no-plots"}, &err), 0);
  EXPECT_NE(err.find("left by a run that was killed"), std::string::npos) << err;
  EXPECT_TRUE(leftovers(d.out).empty()) << leftovers(d.out).front();
  EXPECT_EQ(whole_run(d.out, "alpha"), "");
}

TEST(RunDirectory, OlderResultsWithoutAManifestAreReplacedAndTheirPartialFilesGo) {
  const Dirs d = setup("rundir-legacy");
  write_text(d.out / "result.h5", "old");
  write_text(d.out / "summary.json", "{\"scene\": \"alpha\"}\n");
  write_text(d.out / "report.md", "old report");
  write_text(d.out / "temperature.png", "old picture");
  write_text(d.out / "result.h5.partial-12345", "killed");
  ASSERT_EQ(run({"run", d.a.string(), "--out", d.out.string(), "-q", "--no-plots"}), 0);
  EXPECT_EQ(whole_run(d.out, "alpha"), "");
  EXPECT_FALSE(fs::exists(d.out / "temperature.png"));
  EXPECT_FALSE(fs::exists(d.out / "result.h5.partial-12345"));
}

// On a file system without RENAME_EXCHANGE the swap takes two renames; a run
// killed between them leaves the target missing, and the next run puts the
// previous results back before it starts.
TEST(RunDirectory, TwoRenamesAreRecoveredAfterAKillBetweenThem) {
  const Dirs d = setup("rundir-tworenames");
  ASSERT_EQ(run({"run", d.a.string(), "--out", d.out.string(), "-q", "--no-plots"}), 0);
  const fs::path target = fs::weakly_canonical(d.out);
  fs::rename(target, d.root / ".results.old-777-xyzxyz");  // the first rename of a killed run
  write_text(d.root / ".results.tmp-777-xyzxyz" / "result.h5", "complete or not");
  EXPECT_TRUE(clear_leftovers(target).size() == 2);
  EXPECT_EQ(whole_run(target, "alpha"), "");
  EXPECT_TRUE(leftovers(target).empty());
  // And the two renames themselves, to the end.
  const fs::path staging = d.root / ".results.tmp-1-aaaaaa";
  write_text(staging / "x.txt", "new");
  const fs::path previous = swap_into_place(staging, target, SwapMethod::two_renames);
  EXPECT_EQ(read_text(target / "x.txt"), "new");
  EXPECT_EQ(whole_run(previous, "alpha"), "");
}

TEST(RunDirectory, AnInputErrorLeavesNothingAnywhere) {
  const Dirs d = setup("rundir-nothing");
  const fs::path out = d.root / "deep" / "er" / "results";
  EXPECT_EQ(run({"run", d.a.string(), "--out", out.string(), "-q", "--set", "particles.r=2"}), 2);
  EXPECT_FALSE(fs::exists(d.root / "deep"));
}

TEST(RunDirectory, ASweepIsWholeWithItsVariantsInside) {
  const Dirs d = setup("rundir-sweep");
  write_text(d.root / "sweep.toml", std::string(kSceneA) +
                                        "[sweep]\nvariants = [\"particles.r=0.2\", \"particles.r=0.6\"]\n"
                                        "labels = [\"low\", \"high\"]\n[output]\nplots = false\n");
  ASSERT_EQ(run({"run", (d.root / "sweep.toml").string(), "--out", d.out.string(), "-q"}), 0);
  EXPECT_EQ(whole_run(d.out, "alpha"), "");
  EXPECT_EQ(whole_run(d.out / "0-low", "alpha/low"), "");
  EXPECT_EQ(whole_run(d.out / "1-high", "alpha/high"), "");
  EXPECT_NE(read_text(d.out / kManifestFile).find("1-high/result.h5"), std::string::npos);
}

// `shockgas animate DIR` adds files to a finished run: they join its manifest,
// so the directory stays whole and the scene can run into it again.
TEST(RunDirectory, AnimateKeepsTheManifestWhole) {
  const Dirs d = setup("rundir-animate");
  write_text(d.a, std::string(kSceneA) + "[output]\nplots = false\nanimation = true\nanimation_frames = 3\n");
  ASSERT_EQ(run({"run", d.a.string(), "--out", d.out.string(), "-q"}), 0);
  const fs::path script = d.root / "fake_animate.py";
  write_text(script, "import os, sys\nopen(os.path.join(sys.argv[1], 'animation.gif'), 'w').write('gif')\n");
  setenv("SHOCKGAS_ANIMATE_SCRIPT", script.c_str(), 1);
  const int animated = run({"animate", d.out.string()});
  unsetenv("SHOCKGAS_ANIMATE_SCRIPT");
  ASSERT_EQ(animated, 0);
  ASSERT_TRUE(fs::exists(d.out / "animation.gif"));
  EXPECT_EQ(whole_run(d.out, "alpha"), "");
  EXPECT_EQ(run({"run", d.a.string(), "--out", d.out.string(), "-q"}), 0);
}

}  // namespace
}  // namespace shockgas::app
