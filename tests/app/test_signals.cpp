// Signals (findings: SIGINT while the plots were drawn was ignored; a Ctrl-C to
// the process group printed a Python traceback and "the results are complete";
// after SIGTERM the plotting process went on writing pictures): SIGINT and
// SIGTERM stop a run at any stage with 130 and 143, leave the output directory
// as it was and no process behind; the library itself installs no handler.
#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <string>
#include <thread>

#include "child_run.hpp"
#include "run_dir_checks.hpp"
#include "shockgas/app/input/scene_parser.hpp"
#include "shockgas/app/jobs/run_scene.hpp"
#include "shockgas/core/interrupt.hpp"
#include "two_runs.hpp"

namespace shockgas::app {
namespace {

using namespace testing;
using namespace std::chrono_literals;

using Scenario = TwoRuns;

// The previous results (alpha) in out, beta to run over them with a slow plotter.
Scenario setup(const std::string& name) { return alpha_done(fresh_dir(name), 30); }

// Waits until pred() or the time is up.
template <class Pred>
bool eventually(Pred pred, std::chrono::milliseconds limit = 60000ms) {
  const auto end = std::chrono::steady_clock::now() + limit;
  while (!pred()) {
    if (std::chrono::steady_clock::now() > end) return false;
    std::this_thread::sleep_for(10ms);
  }
  return true;
}

void expect_unchanged(const Scenario& s) {
  EXPECT_EQ(whole_run(s.out, "alpha"), "");
  EXPECT_TRUE(leftovers(s.out).empty()) << leftovers(s.out).front();
}

// While the particles are computed: the run stops at its next progress report.
TEST(Signals, SigintAndSigtermDuringComputeEndTheRunWith130And143) {
  for (const int sig : {SIGINT, SIGTERM}) {
    const Scenario s = setup("signals-compute-" + std::to_string(sig));
    Child run({"run", s.b.string(), "--out", s.out.string(), "-q", "--force", "--set", "initial.N=200000",
               "--set", "particles.t_end=2000", "--set", "continuum.cells=4000"},
              with_env({{"SHOCKGAS_FAULT", "compute:1:stop"}}));
    ASSERT_TRUE(run.wait_stopped()) << run.err();  // it is computing
    kill(run.pid(), sig);
    kill(run.pid(), SIGCONT);
    EXPECT_EQ(run.wait(), 128 + sig) << run.err();
    EXPECT_NE(run.err().find("interrupted by signal " + std::to_string(sig) + " (SIG"), std::string::npos)
        << run.err();
    expect_unchanged(s);
  }
}

// While the plots are drawn: the plotting process is stopped too and waited
// for; no picture appears after shockgas has ended.
TEST(Signals, SigintAndSigtermDuringPlottingStopThePlotterToo) {
  for (const int sig : {SIGINT, SIGTERM}) {
    const Scenario s = setup("signals-plot-" + std::to_string(sig));
    Child run({"run", s.b.string(), "--out", s.out.string(), "-q", "--force"},
              with_env({{"SHOCKGAS_PLOT_SCRIPT", s.script.string()}}));
    const fs::path pid_file = s.root / "plotter.pid";
    ASSERT_TRUE(eventually([&] { return !read_text(pid_file).empty(); })) << run.err();
    const pid_t plotter = std::stoi(read_text(pid_file));
    kill(run.pid(), sig);
    EXPECT_EQ(run.wait(), 128 + sig) << run.err();
    EXPECT_FALSE(process_alive(plotter)) << "the plotting process outlived shockgas";
    EXPECT_EQ(run.err().find("the results are complete"), std::string::npos) << run.err();
    expect_unchanged(s);
  }
}

// Ctrl-C at a terminal: SIGINT to the whole foreground process group. The
// plotter runs in a group of its own, so shockgas alone receives it, stops the
// plotter, and no Python traceback is printed. With the real plotting script.
TEST(Signals, CtrlCToTheProcessGroupWhilePlottingPrintsNoTraceback) {
  if (std::system("/usr/bin/python3 -c 'import matplotlib, h5py' 2>/dev/null") != 0)
    GTEST_SKIP() << "/usr/bin/python3 without matplotlib and h5py (scripts/setup installs them)";
  const Scenario s = setup("signals-ctrlc");
  Child run({"run", s.b.string(), "--out", s.out.string(), "-q", "--force"}, in_own_group());
  ASSERT_TRUE(eventually([&] { return !children_of(run.pid()).empty(); })) << run.err();
  std::this_thread::sleep_for(300ms);  // the plotter is importing matplotlib, or drawing
  const pid_t plotter = children_of(run.pid()).front();
  kill(-run.pid(), SIGINT);
  EXPECT_EQ(run.wait(), 130) << run.err();
  EXPECT_EQ(run.err().find("Traceback"), std::string::npos) << run.err();
  EXPECT_EQ(run.err().find("the results are complete"), std::string::npos) << run.err();
  EXPECT_TRUE(eventually([&] { return !process_alive(plotter); }, 5000ms));
  expect_unchanged(s);
}

// The library polls the request; it never installs a handler (a Python host or
// an MPI launcher owns the signals).
TEST(Signals, TheLibraryInstallsNoHandlerAndStopsOnARequest) {
  const Scenario s = setup("signals-library");
  const Scene scene = load_scene(s.b.string());
  RunOptions options;
  options.out_dir = s.out.string();
  options.progress = false;
  options.plots = false;
  options.force = true;
  request_interrupt(InterruptMode::abort, SIGINT);
  EXPECT_THROW(run_scene(scene, options), Interrupted);
  clear_interrupt();
  expect_unchanged(s);
  struct sigaction now {};
  for (const int sig : {SIGINT, SIGTERM}) {
    sigaction(sig, nullptr, &now);
    EXPECT_EQ(now.sa_handler, SIG_DFL) << sig;
  }
}

}  // namespace
}  // namespace shockgas::app
