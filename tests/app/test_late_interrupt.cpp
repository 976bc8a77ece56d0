// An interruption after the particles (finding: SIGTERM while the results were
// written or the plots drawn threw the whole ensemble away, the checkpoint on
// disk holding only what its last periodic save had): a run that has saved a
// checkpoint saves every realization when the particles end, so that a resumed
// run goes straight to the writing and equals the uninterrupted one.
#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <string>
#include <thread>
#include <vector>

#include "app/run_comparison.hpp"
#include "child_run.hpp"
#include "run_dir_checks.hpp"
#include "shockgas/app/records/checkpoint.hpp"

namespace shockgas::app {
namespace {

using namespace testing;

TEST(LateInterrupt, SigtermWhileThePlotsAreDrawnKeepsEveryRealization) {
  const fs::path root = fresh_dir("late-interrupt");
  const fs::path scene = root / "alpha.toml", whole = root / "whole", out = root / "D";
  // Realizations of tens of ms at least, each saving its state every 6 ms of
  // its run: a checkpoint is on disk before the particles end.
  write_text(
      scene,
      "[scene]\nname = \"alpha\"\n[initial]\nN = 20000\n[particles]\nr = 0.5\nt_end = 100\nsamples = 8\n"
      "[continuum]\nsolvers = [\"hopf_lax\"]\ncells = 500\n[compare]\n");
  const std::vector<std::string> sets{"--set", "particles.realizations=3", "--set",
                                      "output.checkpoint_minutes=1e-4"};
  std::vector<std::string> args{"run", scene.string(), "--out", whole.string(), "-q", "--no-plots"};
  args.insert(args.end(), sets.begin(), sets.end());
  ASSERT_EQ(run_child(args).first, 0);
  args = {"run", scene.string(), "--out", out.string(), "-q"};
  args.insert(args.end(), sets.begin(), sets.end());
  Child stopped(args, with_env({{"SHOCKGAS_PLOT_SCRIPT", fake_plot_script(root, 60).string()}}));
  const fs::path plotting = root / "plotter.pid";  // written by the plotting script as it starts
  for (int k = 0; k < 1000 && !fs::exists(plotting); ++k)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  ASSERT_TRUE(fs::exists(plotting)) << stopped.err();
  kill(stopped.pid(), SIGTERM);
  ASSERT_EQ(stopped.wait(), 128 + SIGTERM) << stopped.err();
  ASSERT_TRUE(fs::exists(checkpoint_path(out))) << stopped.err();
  EXPECT_EQ(stopped.err(), "shockgas: interrupted by signal 15 (SIGTERM); all 3 realizations are kept in " +
                               checkpoint_path(out).string() + "; continue with: shockgas run --resume " +
                               out.string() + "\n");

  const auto [code, err] = run_child({"run", "--resume", out.string(), "--no-plots"});
  ASSERT_EQ(code, 0) << err;
  EXPECT_NE(err.find("3 of 3 realizations kept from the checkpoint"), std::string::npos) << err;
  EXPECT_FALSE(fs::exists(checkpoint_path(out)));
  const auto differences = result_differences(whole, out);
  EXPECT_TRUE(differences.empty()) << differences.front();
}

}  // namespace
}  // namespace shockgas::app
