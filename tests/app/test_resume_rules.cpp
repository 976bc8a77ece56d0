// What resume accepts and refuses with running states beside the checkpoint
// (findings of a hostile pass: `--resume DIR SCENE --set particles.threads=2`,
// as docs/cluster.md shows it, was refused as "another scene" whenever a
// realization had saved its state, and so was another checkpoint_minutes; a
// damaged states file of a running realization 0 was found only after the
// whole resumed run (exit 1), and a cut or missing one was refused, where a
// finished realization 0 whose states file is not whole runs again).
#include <gtest/gtest.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "child_run.hpp"
#include "run_dir_checks.hpp"

namespace shockgas::app {
namespace {

using namespace testing;

// Realization 0 (one thread: it runs first) keeps its states apart (no
// comparison), a snapshot at t = 0 among them: its states file holds bytes
// from the first moment on.
const char* kScene =
    "[scene]\nname = \"resumed\"\n[initial]\nN = 20000\n[particles]\nr = 0.5\nt_end = 200\n"
    "realizations = 2\nsnapshots = [0, 0.5]\n[output]\nplots = false\n";

// A run of the scene into root/run stopped by SIGTERM while realization 0
// runs: its checkpoint, realization 0's state and its states file.
fs::path interrupted(const fs::path& root) {
  write_text(root / "scene.toml", kScene);
  fs::path run = root / "run";
  Child child({"run", (root / "scene.toml").string(), "--out", run.string(), "-q"},
              with_env({{"SHOCKGAS_FAULT", "compute:2:stop"}}));
  EXPECT_TRUE(child.wait_stopped()) << child.err();
  kill(child.pid(), SIGTERM);
  kill(child.pid(), SIGCONT);
  EXPECT_EQ(child.wait(), 128 + SIGTERM) << child.err();
  EXPECT_TRUE(fs::exists(run / "checkpoint.run-0-0.bin")) << child.err();
  return run;
}

TEST(ResumeRules, TheThreadsAndTheCheckpointIntervalMayChange) {
  const fs::path root = fresh_dir("resume-threads");
  const fs::path run = interrupted(root);
  // Realization 1 has a state too where it had started when the signal came.
  const int saved = 1 + static_cast<int>(fs::exists(run / "checkpoint.run-0-1.bin"));
  const auto [code, err] =
      run_child({"run", "--resume", run.string(), (root / "scene.toml").string(), "-q", "--set",
                 "particles.threads=2", "--set", "output.checkpoint_minutes=5"});
  EXPECT_EQ(code, 0) << err;
  EXPECT_NE(
      err.find(std::to_string(saved) + (saved == 1 ? " continues" : " continue") + " from a saved state"),
      std::string::npos)
      << err;
  EXPECT_EQ(whole_run(run, "resumed"), "");
}

// A running realization 0 goes on writing its states file from where its
// save left it: when the file is not as the save recorded it, realization 0
// starts again (and the run says so), never ending after the work.
TEST(ResumeRules, ARunningRealizationWhoseStatesFileIsNotWholeStartsAgain) {
  const fs::path root = fresh_dir("resume-states");
  const fs::path pristine = interrupted(root);
  const fs::path states = "states-0.bin.tmp";
  ASSERT_GT(fs::file_size(pristine / states), 1000u);
  for (const std::string damage : {"damaged", "cut", "missing"}) {
    const fs::path run = root / damage;
    fs::copy(pristine, run, fs::copy_options::recursive);
    if (damage == "damaged")
      overwrite_eight_bytes(run / states, 64);
    else if (damage == "cut")
      fs::resize_file(run / states, fs::file_size(run / states) / 2);
    else
      fs::remove(run / states);
    const auto [code, err] = run_child({"run", "--resume", run.string(), "-q"});
    EXPECT_EQ(code, 0) << damage << ": " << err;
    EXPECT_NE(err.find("realization 0 of ensemble 0 runs again: "), std::string::npos)
        << damage << ": " << err;
    EXPECT_EQ(whole_run(run, "resumed"), "") << damage;
  }
}

}  // namespace
}  // namespace shockgas::app
