// A plotting script that fails (finding: its Python traceback went raw to
// stderr): with room on the disk the results are complete without the
// pictures. The run ends with exit 0 and says why in one line; what the script
// said is kept in plots.log beside the results, in their manifest; a picture
// it left half-written (*.partial) is not kept.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>

#include "child_run.hpp"
#include "run_dir_checks.hpp"
#include "two_runs.hpp"

namespace shockgas::app {
namespace {

using namespace testing;

TEST(PlotFailures, AFailedScriptIsOneWarningAndItsMessagesAreKeptInPlotsLog) {
  const TwoRuns s = alpha_done(fresh_dir("plot-failure"));
  const fs::path script = s.root / "failing_plot.py";
  write_text(script,
             "import os, sys\n"
             "open(os.path.join(sys.argv[1], 'whole.png'), 'w').write('picture')\n"
             "open(os.path.join(sys.argv[1], 'half.png.partial'), 'w').write('pict')\n"
             "raise ValueError('x and y must have the same first dimension')\n");
  const auto [code, err] = run_child({"run", s.b.string(), "--out", s.out.string(), "-q", "--force"},
                                     with_env({{"SHOCKGAS_PLOT_SCRIPT", script.string()}}));
  EXPECT_EQ(code, 0) << err;
  EXPECT_EQ(err,
            "shockgas: warning: plots failed: ValueError: x and y must have the same first dimension "
            "(failing_plot.py, exit 1; its messages are kept in plots.log)\n");
  EXPECT_EQ(whole_run(s.out, "beta"), "");
  const std::string log = read_text(s.out / "plots.log");
  EXPECT_NE(log.find("Traceback (most recent call last):"), std::string::npos) << log;
  EXPECT_NE(log.find("ValueError: x and y must have the same first dimension"), std::string::npos) << log;
  EXPECT_TRUE(fs::exists(s.out / "whole.png"));
  EXPECT_FALSE(fs::exists(s.out / "half.png.partial"));
}

// What a script that succeeds says (a warning of its own) still reaches stderr.
TEST(PlotFailures, WhatASucceedingScriptSaysIsPassedOn) {
  const TwoRuns s = alpha_done(fresh_dir("plot-says"));
  const fs::path script = s.root / "talking_plot.py";
  write_text(script, "import sys\nprint('talking_plot.py: warning: ffmpeg not found', file=sys.stderr)\n");
  const auto [code, err] = run_child({"run", s.b.string(), "--out", s.out.string(), "-q", "--force"},
                                     with_env({{"SHOCKGAS_PLOT_SCRIPT", script.string()}}));
  EXPECT_EQ(code, 0) << err;
  EXPECT_EQ(err, "talking_plot.py: warning: ffmpeg not found\n");
  EXPECT_EQ(whole_run(s.out, "beta"), "");
  EXPECT_FALSE(fs::exists(s.out / "plots.log"));
}

}  // namespace
}  // namespace shockgas::app
