// A reader of stderr that goes away and a terminal that hangs up (findings of
// a hostile pass: `shockgas run ... 2>&1 | head -1` killed the run with
// SIGPIPE, exit 141, the run lost; SIGHUP ended a run with 129 and no
// checkpoint). A closed pipe never loses a run; SIGHUP saves as SIGTERM does.
#include <gtest/gtest.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <string>

#include "child_run.hpp"
#include "run_dir_checks.hpp"

namespace shockgas::app {
namespace {

using namespace testing;

// The child's stderr a pipe whose reader has gone: every write to it fails.
Options stderr_to_a_closed_pipe(std::map<std::string, std::string> env) {
  Options o = with_env(std::move(env));
  o.in_child = [] {
    int ends[2];
    if (pipe(ends) != 0) _exit(125);
    close(ends[0]);
    dup2(ends[1], STDERR_FILENO);
    close(ends[1]);
  };
  return o;
}

// The run warns on stderr (its plotting script fails) after the work: the
// warning is lost, the run is not.
TEST(HangUps, AReaderOfStderrThatGoesAwayEndsNoRun) {
  const fs::path root = fresh_dir("hangup-pipe");
  write_text(root / "scene.toml", kSceneA);
  write_text(root / "failing_plot.py", "import sys\nsys.exit(3)\n");
  Child run({"run", (root / "scene.toml").string(), "--out", (root / "out").string()},
            stderr_to_a_closed_pipe({{"SHOCKGAS_PLOT_SCRIPT", (root / "failing_plot.py").string()}}));
  EXPECT_EQ(run.wait(), 0);
  EXPECT_EQ(whole_run(root / "out", "alpha"), "");
}

// SIGHUP while the particles are computed: a checkpoint, exit 129, and the
// run resumes from it to its end.
TEST(HangUps, SighupSavesACheckpointAsSigtermDoes) {
  const fs::path root = fresh_dir("hangup-signal");
  write_text(root / "scene.toml",
             "[scene]\nname = \"hangup\"\n[initial]\nN = 20000\n[particles]\nr = 0.5\nt_end = 200\n"
             "realizations = 2\n[output]\nplots = false\n");
  const fs::path out = root / "out";
  Child run({"run", (root / "scene.toml").string(), "--out", out.string(), "-q"},
            with_env({{"SHOCKGAS_FAULT", "compute:2:stop"}}));
  ASSERT_TRUE(run.wait_stopped()) << run.err();
  kill(run.pid(), SIGHUP);
  kill(run.pid(), SIGCONT);
  EXPECT_EQ(run.wait(), 128 + SIGHUP) << run.err();
  EXPECT_NE(run.err().find("interrupted by signal 1 (SIGHUP); checkpoint written"), std::string::npos)
      << run.err();
  ASSERT_TRUE(fs::exists(out / "checkpoint.bin")) << run.err();
  const auto [code, err] = run_child({"run", "--resume", out.string(), "-q"});
  EXPECT_EQ(code, 0) << err;
  EXPECT_EQ(whole_run(out, "hangup"), "");
}

}  // namespace
}  // namespace shockgas::app
