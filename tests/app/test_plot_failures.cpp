// A plotting script that fails (finding: its Python traceback went raw to
// stderr): with room on the disk the results are complete without the
// pictures. The run ends with exit 0 and says why in one line; what the script
// said is kept in plots.log beside the results, in their manifest; a picture
// it left half-written (*.partial) is not kept.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <string>
#include <thread>

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

// Plots that fail for memory half-way (finding of a hostile pass: under ulimit
// -v two of three pictures and exit 0, the report silent about the third): the
// report says that pictures are missing, and where the script's words are.
TEST(PlotFailures, TheReportSaysThatPicturesAreMissing) {
  const TwoRuns s = alpha_done(fresh_dir("plot-missing"));
  const fs::path script = s.root / "failing_plot.py";
  write_text(script,
             "import os, sys\n"
             "open(os.path.join(sys.argv[1], 'whole.png'), 'w').write('picture')\n"
             "raise MemoryError()\n");
  const auto [code, err] = run_child({"run", s.b.string(), "--out", s.out.string(), "-q", "--force"},
                                     with_env({{"SHOCKGAS_PLOT_SCRIPT", script.string()}}));
  EXPECT_EQ(code, 0) << err;
  EXPECT_NE(read_text(s.out / "report.html")
                .find("The plotting script failed: 1 picture was drawn before it stopped, and the others "
                      "are missing."),
            std::string::npos);
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

// The script reads nothing (finding: ffmpeg, started by the animation script
// in a background process group of the terminal, read it and was stopped by
// SIGTTIN: the run never ended), and what it prints on stdout comes after the
// phase's line with what it says on stderr, not in the middle of that line.
// The command's stdin here is a file, which the script must not see.
TEST(PlotFailures, TheScriptReadsNothingAndItsStdoutIsPassedOn) {
  const TwoRuns s = alpha_done(fresh_dir("plot-stdin"));
  const fs::path script = s.root / "reading_plot.py";
  write_text(script, "import os\nprint('stdin of the script: ' + os.readlink('/proc/self/fd/0'))\n");
  Options o = with_env({{"SHOCKGAS_PLOT_SCRIPT", script.string()}});
  const std::string stdin_file = script.string();
  o.in_child = [&stdin_file] {
    const int fd = ::open(stdin_file.c_str(), O_RDONLY);
    if (fd >= 0) ::dup2(fd, 0);
  };
  const auto [code, err] = run_child({"run", s.b.string(), "--out", s.out.string(), "-q", "--force"}, o);
  EXPECT_EQ(code, 0) << err;
  EXPECT_EQ(err, "stdin of the script: /dev/null\n");
  EXPECT_EQ(whole_run(s.out, "beta"), "");
}

// Alpha with the frames of an animation (and no pictures) into s.out: its exit code.
int run_with_frames(const TwoRuns& s) {
  const fs::path scene = s.root / "frames.toml";
  write_text(scene,
             std::string(kSceneA) + "[output]\nplots = false\nanimation = true\nanimation_frames = 4\n");
  return run_child({"run", scene.string(), "--out", s.out.string(), "-q", "--force"}).first;
}

// `shockgas animate` stopped by SIGTERM leaves the finished directory as it was
// (finding: ffmpeg, which the animation script had started, went on writing
// animation.mp4 after the command had exited, and the movie no longer matched
// the manifest): what the script started is stopped with it, and its
// half-written file is removed. The stand-in script starts a writer that
// ignores SIGTERM, as an encoder flushing its file would outlast it.
TEST(PlotFailures, AnInterruptedAnimationLeavesNothingWriting) {
  const TwoRuns s = alpha_done(fresh_dir("animate-stopped"));
  ASSERT_EQ(run_with_frames(s), 0);
  // The script draws into the directory it is given (animate's staging
  // directory) and says where its file is.
  const fs::path script = s.root / "writing_animation.py", where = s.root / "partial.path";
  write_text(
      script,
      "import subprocess, sys, time\n"
      "partial = sys.argv[1] + '/animation.mp4.partial'\n"
      "subprocess.Popen(['sh', '-c', 'trap \"\" TERM; while :; do echo x >> \"$0\"; sleep 0.02; done', "
      "partial])\n"
      "open('" +
          where.string() +
          "', 'w').write(partial)\n"
          "time.sleep(60)\n");
  Child animate({"animate", s.out.string()}, with_env({{"SHOCKGAS_ANIMATE_SCRIPT", script.string()}}));
  fs::path partial;
  for (int k = 0; k < 500 && (partial.empty() || !fs::exists(partial)); ++k) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    partial = read_text(where);
  }
  ASSERT_TRUE(fs::exists(partial)) << animate.err();
  kill(animate.pid(), SIGTERM);
  EXPECT_EQ(animate.wait(), 128 + SIGTERM) << animate.err();
  std::this_thread::sleep_for(std::chrono::milliseconds(300));  // 15 turns of the writer's loop
  EXPECT_FALSE(fs::exists(partial)) << animate.err();
  EXPECT_EQ(whole_run(s.out, "alpha"), "");
}

// A script that says more than is kept: plots.log says that its start is cut
// (found: 64 kB kept without a word of the 285 kB said).
TEST(PlotFailures, ALogThatIsCutSaysSo) {
  const TwoRuns s = alpha_done(fresh_dir("plot-noisy"));
  const fs::path script = s.root / "noisy_plot.py";
  write_text(script,
             "import sys\nfor k in range(5000): print('noisy line %05d' % k + 'x' * 40, file=sys.stderr)\n"
             "raise ValueError('late')\n");
  const auto [code, err] = run_child({"run", s.b.string(), "--out", s.out.string(), "-q", "--force"},
                                     with_env({{"SHOCKGAS_PLOT_SCRIPT", script.string()}}));
  EXPECT_EQ(code, 0) << err;
  const std::string log = read_text(s.out / "plots.log");
  EXPECT_EQ(log.rfind("[noisy_plot.py said more: only its last 64 kB are kept here]\n", 0), 0u)
      << log.substr(0, 200);
  EXPECT_NE(log.find("ValueError: late"), std::string::npos);
  EXPECT_EQ(whole_run(s.out, "beta"), "");
}

// In a sweep each variant's warning names its own log (found: three identical
// lines, "its messages are kept in plots.log", for three different logs).
TEST(PlotFailures, ASweepsWarningsNameTheVariantsLog) {
  const fs::path root = fresh_dir("plot-sweep"), scene = root / "sweep.toml", out = root / "S";
  write_text(scene,
             "[scene]\nname = \"sw\"\n[initial]\nN = 200\n[particles]\nt_end = 5\n"
             "[sweep]\nvariants = [\"particles.r=0.1\", \"particles.r=0.2\"]\nlabels = [\"a\", \"b\"]\n");
  const fs::path script = root / "failing_plot.py";
  write_text(script, "raise ValueError('no picture')\n");
  const auto [code, err] = run_child({"run", scene.string(), "--out", out.string(), "-q"},
                                     with_env({{"SHOCKGAS_PLOT_SCRIPT", script.string()}}));
  ASSERT_EQ(code, 0) << err;
  EXPECT_NE(err.find("its messages are kept in 0-a/plots.log)"), std::string::npos) << err;
  EXPECT_NE(err.find("its messages are kept in 1-b/plots.log)"), std::string::npos) << err;
  EXPECT_TRUE(fs::exists(out / "0-a" / "plots.log")) << err;
}

// `shockgas animate` that succeeds after one that failed leaves no
// animation.log of the failure (found: kept, and listed in the manifest).
TEST(PlotFailures, ASucceedingAnimationRemovesTheLogOfAFailedOne) {
  const TwoRuns s = alpha_done(fresh_dir("animate-again"));
  ASSERT_EQ(run_with_frames(s), 0);
  const fs::path failing = s.root / "failing.py", working = s.root / "working.py";
  write_text(failing, "raise ValueError('no movie')\n");
  write_text(working,
             "import os, sys\nopen(os.path.join(sys.argv[1], 'animation.png'), 'w').write('frame')\n");
  EXPECT_EQ(
      run_child({"animate", s.out.string()}, with_env({{"SHOCKGAS_ANIMATE_SCRIPT", failing.string()}})).first,
      0);
  ASSERT_TRUE(fs::exists(s.out / "animation.log"));
  EXPECT_EQ(
      run_child({"animate", s.out.string()}, with_env({{"SHOCKGAS_ANIMATE_SCRIPT", working.string()}})).first,
      0);
  EXPECT_FALSE(fs::exists(s.out / "animation.log"));
  EXPECT_EQ(read_text(s.out / "manifest.json").find("animation.log"), std::string::npos);
  EXPECT_EQ(whole_run(s.out, "alpha"), "");
}

// ffmpeg that cannot write its file's trailer on a full disk says "Error
// writing trailer of ...: No space left on device" and still exits with 0 (as
// ffmpeg 5 does; finding: `shockgas animate` on a nearly full disk renamed the
// cut-short movie over the run's whole one). A stand-in ffmpeg on PATH does
// just that; the real animation script must take it as the failure it is.
TEST(PlotFailures, AnEncoderThatCutsItsFileShortButExitsWithZeroReplacesNothing) {
  if (std::system("/usr/bin/python3 -c 'import matplotlib, h5py' 2>/dev/null") != 0)
    GTEST_SKIP() << "/usr/bin/python3 lacks matplotlib or h5py: the real animation script cannot run";
  const TwoRuns s = alpha_done(fresh_dir("animate-cut-short"));
  ASSERT_EQ(run_with_frames(s), 0);
  const std::string before = read_text(s.out / "manifest.json");
  const fs::path bin = s.root / "bin";
  fs::create_directories(bin);
  // ffmpeg 5's line, and the later versions' after the muxer's name
  for (const std::string said :
       {"Error writing trailer of $last", "[out#0/mp4 @ 0x5581] Error writing trailer"}) {
    write_text(bin / "ffmpeg",
               "#!/bin/sh\nfor last; do :; done\ncat > /dev/null\nhead -c 1000 /dev/zero > \"$last\"\n"
               "echo \"" +
                   said + ": No space left on device\" >&2\nexit 0\n");
    fs::permissions(bin / "ffmpeg", fs::perms::owner_all);
    const auto [code, err] = run_child({"animate", s.out.string()},
                                       with_env({{"PATH", bin.string() + ":" + std::getenv("PATH")}}));
    EXPECT_NE(code, 0) << err;
    EXPECT_NE(err.find("animation.mp4: No space left on device"), std::string::npos) << err;
    EXPECT_EQ(read_text(s.out / "manifest.json"), before);
    EXPECT_EQ(whole_run(s.out, "alpha"), "");
    for (const auto& entry : fs::directory_iterator(s.out))
      EXPECT_NE(entry.path().extension(), ".partial") << entry.path();
  }
}

}  // namespace
}  // namespace shockgas::app
