// A full or read-only disk (findings: a run on a full 2 MB file system died
// with SIGSEGV in the HDF5 library's shutdown after a failed write, leaving the
// new report beside the old results; a read-only --out gave exit 1): each test
// mounts a small tmpfs (skipped with a message where it cannot).
#include <gtest/gtest.h>
#include <sys/mount.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <random>
#include <string>

#include "child_run.hpp"
#include "run_dir_checks.hpp"
#include "shockgas/app/directory/result_check.hpp"
#include "shockgas/app/files/manifest.hpp"
#include "shockgas/app/output/hdf5_file.hpp"
#include "shockgas/app/report/plots.hpp"
#include "shockgas/core/error.hpp"
#include "two_runs.hpp"

namespace shockgas::app {
namespace {

using namespace testing;

// A tmpfs of `size` mounted for the test's lifetime (root, or CAP_SYS_ADMIN, needed).
class SmallDisk {
 public:
  SmallDisk(const std::string& name, const std::string& size) : dir_(fresh_dir(name)) {
    mounted_ = mount("tmpfs", dir_.c_str(), "tmpfs", 0, ("size=" + size).c_str()) == 0;
  }
  ~SmallDisk() {
    if (mounted_) umount2(dir_.c_str(), MNT_DETACH);
  }
  bool mounted() const { return mounted_; }
  const fs::path& dir() const { return dir_; }
  void remount_read_only() { mount("tmpfs", dir_.c_str(), "tmpfs", MS_REMOUNT | MS_RDONLY, nullptr); }
  // Fills the disk up to `keep` free bytes.
  void fill(std::uintmax_t keep) {
    const auto free = fs::space(dir_).available;
    if (free <= keep) return;
    std::FILE* f = std::fopen((dir_ / "filler").c_str(), "wb");
    std::vector<char> block(1 << 16, 'x');
    for (std::uintmax_t left = free - keep; left > 0;) {
      const std::size_t n = std::min<std::uintmax_t>(left, block.size());
      if (std::fwrite(block.data(), 1, n, f) != n) break;
      left -= n;
    }
    std::fclose(f);
  }

 private:
  fs::path dir_;
  bool mounted_ = false;
};

#define REQUIRE_MOUNTED(disk) \
  if (!(disk).mounted()) GTEST_SKIP() << "cannot mount a tmpfs here (needs root or CAP_SYS_ADMIN)"

// The finding as reported: the default scene with N = 5000 on a 2 MB tmpfs.
TEST(FullDisk, TheDefaultSceneOnATwoMegabyteDiskEndsCleanlyAndWritesNothing) {
  SmallDisk disk("fulldisk-default", "2m");
  REQUIRE_MOUNTED(disk);
  const fs::path scene = fs::path(SHOCKGAS_SOURCE_DIR) / "data/scenes/default.toml";
  const auto [code, err] = run_child(
      {"run", scene.string(), "--set", "initial.N=5000", "--out", (disk.dir() / "D").string(), "-q"});
  EXPECT_TRUE(code == 1 || code == 2) << "status " << code << "\n" << err;
  EXPECT_FALSE(fs::exists(disk.dir() / "D"));
  EXPECT_TRUE(leftovers(disk.dir() / "D").empty());
}

// The disk fills up while the run computes (it stops at its first progress
// report, SHOCKGAS_FAULT=compute:1:stop, while the test fills the disk): the
// write of the result fails, as in the finding (in whichever HDF5 call first
// meets the full disk: the initial state is written in chunks while the run
// computes, the rest at its end, and HDF5 may buffer a write until H5Dclose or
// H5Fclose), and the run ends with exit 1 (not SIGSEGV in the HDF5 library's exit
// handler) and a message naming the file, the cause and the room left; the
// directory keeps the previous, complete results.
TEST(FullDisk, ADiskThatFillsDuringTheRunLeavesThePreviousResults) {
  SmallDisk disk("fulldisk-during", "2m");
  REQUIRE_MOUNTED(disk);
  const TwoRuns s = alpha_done(disk.dir());
  const fs::path& out = s.out;
  ASSERT_EQ(whole_run(out, "alpha"), "");
  Child run({"run", s.b.string(), "--out", out.string(), "-q", "--no-plots", "--force", "--set",
             "particles.spacetime=true", "--set", "particles.spacetime_frames=100"},  // 640 kB of record
            with_env({{"SHOCKGAS_FAULT", "compute:1:stop"}}));
  ASSERT_TRUE(run.wait_stopped()) << run.err();
  disk.fill(20000);
  kill(run.pid(), SIGCONT);
  EXPECT_EQ(run.wait(), 1) << run.err();
  const std::string err = run.err();
  EXPECT_NE(err.find("shockgas: run failed: "), std::string::npos) << err;
  EXPECT_NE(err.find("HDF5: H5"), std::string::npos) << err;
  EXPECT_NE(err.find("result.h5"), std::string::npos) << err;  // the file, not only the dataset
  // named where the user looks for it, not in the staging directory, gone by now
  EXPECT_NE(err.find((fs::weakly_canonical(out) / "result.h5").string()), std::string::npos) << err;
  EXPECT_EQ(err.find(".tmp-"), std::string::npos) << err;
  EXPECT_NE(err.find("(No space left on device)"), std::string::npos) << err;
  EXPECT_NE(err.find("(the file system holding it has "), std::string::npos) << err;  // and the room left
  EXPECT_NE(run.err().find("the results in the output directory are as they were"), std::string::npos)
      << run.err();
  EXPECT_EQ(whole_run(out, "alpha"), "");
  EXPECT_TRUE(leftovers(out).empty()) << leftovers(out).front();
}

// The disk fills while the plots are drawn (finding: a Python traceback, then
// "warning: plots failed (exit 1); the results are complete", then "run failed:
// cannot write report.html", the output directory as it was): the pictures
// cannot be written, so neither can the rest of the run. The run fails once,
// with exit 1 and one line naming the file that could not be written and the
// room left; no traceback, no claim that the results are complete, and the
// previous results stay. The run stops as its plotting script starts (fault
// point "plot"), while the test fills the disk. With the real plotting script
// (its exit 4: "cannot write PATH: REASON"), and with one that knows nothing
// of it and fails on the full disk with a traceback.
TEST(FullDisk, ADiskThatFillsWhileThePlotsAreDrawnFailsTheRunOnce) {
  const bool real = std::system("/usr/bin/python3 -c 'import matplotlib, h5py' 2>/dev/null") == 0;
  if (!real) std::cerr << "the real plotting script not tried: /usr/bin/python3 lacks matplotlib or h5py\n";
  const fs::path elsewhere = fresh_dir("fulldisk-plots-go");
  const fs::path go = elsewhere / "go";  // off the small disk: the generic script waits for it
  const fs::path generic = elsewhere / "generic_plot.py";
  const std::string wait_for_go = "while not os.path.exists('" + go.string() + "'):\n    time.sleep(0.01)\n";
  write_text(generic, "import os, sys, time\n" + wait_for_go +
                          "with open(os.path.join(sys.argv[1], 'picture.png'), 'w') as f:\n"
                          "    f.write('x' * 100000)\n");
  for (const bool with_real_script : {true, false}) {
    if (with_real_script && !real) continue;
    SCOPED_TRACE(with_real_script ? "plots/plot_result.py" : "a script that fails with a traceback");
    SmallDisk disk(with_real_script ? "fulldisk-plots-real" : "fulldisk-plots-generic", "4m");
    REQUIRE_MOUNTED(disk);
    const TwoRuns s = alpha_done(disk.dir());
    fs::remove(go);
    std::map<std::string, std::string> env{{"SHOCKGAS_FAULT", "plot:1:stop"}};
    if (!with_real_script) env["SHOCKGAS_PLOT_SCRIPT"] = generic.string();
    Child run({"run", s.b.string(), "--out", s.out.string(), "-q", "--force"}, with_env(env));
    ASSERT_TRUE(run.wait_stopped()) << run.err();
    disk.fill(0);
    write_text(go, "");
    kill(run.pid(), SIGCONT);
    EXPECT_EQ(run.wait(), 1) << run.err();
    const std::string err = run.err();
    EXPECT_EQ(err.rfind("shockgas: run failed: cannot write ", 0), 0u) << err;
    EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;  // one line: the failure
    EXPECT_NE(err.find(with_real_script ? ".png: No space left on device (the file system holding it has "
                                        : "No space left on device (the file system holding it has "),
              std::string::npos)
        << err;
    EXPECT_NE(err.find("(the results in the output directory are as they were)"), std::string::npos) << err;
    EXPECT_EQ(err.find("Traceback"), std::string::npos) << err;
    EXPECT_EQ(err.find("the results are complete"), std::string::npos) << err;
    EXPECT_EQ(whole_run(s.out, "alpha"), "");
    EXPECT_TRUE(leftovers(s.out).empty()) << leftovers(s.out).front();
  }
}

// A result file that meets a full disk in the middle of its datasets (the
// library flushes chunks as its cache fills): the failure names the call, the
// file's disk being full and the room left there, as every other write of a
// run does (docs/output/run-directory.md), whichever HDF5 call meets it.
TEST(FullDisk, AnHdf5WriteOnAFullDiskNamesTheRoomLeft) {
  SmallDisk disk("fulldisk-hdf5", "1m");
  REQUIRE_MOUNTED(disk);
  std::vector<double> values(1 << 19);  // 4 MiB of doubles that deflate cannot pack: 4 times the disk
  std::mt19937_64 rng(5);
  for (double& x : values) x = std::uniform_real_distribution<double>(0.0, 1.0)(rng);
  std::string message;
  try {
    Hdf5File h5 = Hdf5File::create((disk.dir() / "result.h5").string());
    h5.write("/values", values.data(), {values.size()}, Storage::float64, "1", "noise");
    h5.close();
  } catch (const RunError& e) {
    message = e.what();
  }
  EXPECT_NE(message.find("HDF5: H5"), std::string::npos) << message;
  EXPECT_NE(message.find("(No space left on device)"), std::string::npos) << message;
  EXPECT_NE(message.find("(the file system holding it has 0 bytes free)"), std::string::npos) << message;
}

// Too little room before the run: refused by the preflight (exit 2), naming
// the disk, the estimate and the room; the previous results stay.
TEST(FullDisk, TooLittleRoomIsRefusedBeforeAnyWork) {
  SmallDisk disk("fulldisk-before", "2m");
  REQUIRE_MOUNTED(disk);
  const TwoRuns s = alpha_done(disk.dir());
  const fs::path& out = s.out;
  disk.fill(30000);
  const auto [code, err] =
      run_child({"run", s.b.string(), "--out", out.string(), "-q", "--no-plots", "--force"});
  EXPECT_EQ(code, 2) << err;
  EXPECT_NE(err.find("a file system with room for the results"), std::string::npos) << err;
  EXPECT_EQ(whole_run(out, "alpha"), "");
  EXPECT_TRUE(leftovers(out).empty());
}

TEST(FullDisk, AReadOnlyOutputDirectoryIsBadInput) {
  SmallDisk disk("readonly", "1m");
  REQUIRE_MOUNTED(disk);
  write_text(disk.dir() / "alpha.toml", kSceneA);
  fs::create_directories(disk.dir() / "sub");
  disk.remount_read_only();
  for (const fs::path& out : {disk.dir() / "D", disk.dir() / "sub" / "D", disk.dir() / "sub"}) {
    const auto [code, err] =
        run_child({"run", (disk.dir() / "alpha.toml").string(), "--out", out.string(), "-q", "--no-plots"});
    EXPECT_EQ(code, 2) << out << "\n" << err;
    EXPECT_NE(err.find("Read-only file system"), std::string::npos) << err;
  }
}

TEST(FullDisk, AMountPointIsNotReplaced) {
  SmallDisk disk("mountpoint", "1m");
  REQUIRE_MOUNTED(disk);
  const fs::path scene = disk.dir().parent_path() / "mountpoint-alpha.toml";
  write_text(scene, kSceneA);
  const auto [code, err] =
      run_child({"run", scene.string(), "--out", disk.dir().string(), "-q", "--no-plots"});
  EXPECT_EQ(code, 2) << err;
  EXPECT_NE(err.find("not a mount point"), std::string::npos) << err;
}

// The bench's charts on a full disk (finding: plot_bench.py wrote its PNGs in
// place, so a full disk left a truncated chart beside the CSVs): the chart is
// written whole or not at all, and the script ends with one line and exit 4.
TEST(FullDisk, ABenchChartThatCannotBeWrittenLeavesNoPartOfIt) {
  if (std::system("/usr/bin/python3 -c 'import matplotlib' 2>/dev/null") != 0)
    GTEST_SKIP() << "/usr/bin/python3 lacks matplotlib";
  SmallDisk disk("fulldisk-bench-charts", "1m");
  REQUIRE_MOUNTED(disk);
  write_text(disk.dir() / "stability_cfl.csv",
             "problem,method,cfl,failed,max_tv_rise,rising_steps,tv_ratio,max_ratio,min_rho,l1,what\n"
             "sine,godunov,0.5,no,0,0,0.7,0.8,0.2,0.004,TVD\n"
             "sine,godunov,0.9,no,1e-12,3,0.7,0.8,0.2,0.003,TVD\n"
             "sine,godunov,1.1,yes,0.5,40,2.0,3.0,0.1,0.5,blew up\n");
  disk.fill(8192);  // room for the chart's first bytes only
  const fs::path err = fresh_dir("fulldisk-bench-charts-err") / "stderr";
  const std::string script = (plots_dir() / "plot_bench.py").string();
  const int status = std::system(
      ("/usr/bin/python3 '" + script + "' '" + disk.dir().string() + "' 2>'" + err.string() + "'").c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 4);
  const std::string said = read_text(err);
  EXPECT_EQ(said.rfind("plot_bench.py: cannot write " + (disk.dir() / "stability_cfl.png").string() +
                           ": No space left on device",
                       0),
            0u)
      << said;
  EXPECT_EQ(std::count(said.begin(), said.end(), '\n'), 1) << said;
  for (const auto& e : fs::directory_iterator(disk.dir()))
    EXPECT_EQ(e.path().extension() == ".png" || e.path().extension() == ".partial", false) << e.path();
}

// `shockgas bench` is staged as a run is (finding: on a full disk it left new
// tables, a truncated one among them, beside the charts of the bench before,
// and named a later file with no reason): the disk fills at the second bench,
// which fails with one line, and the first bench's directory is as it was.
TEST(FullDisk, ABenchThatFillsTheDiskLeavesTheEarlierBenchAsItWas) {
  if (std::system("/usr/bin/python3 -c 'import matplotlib' 2>/dev/null") != 0)
    GTEST_SKIP() << "/usr/bin/python3 lacks matplotlib";
  SmallDisk disk("fulldisk-bench", "4m");
  REQUIRE_MOUNTED(disk);
  const fs::path out = disk.dir() / "bench";
  const Options one_section = with_env({{"SHOCKGAS_BENCH_SECTIONS", "continuum_stability"}});
  const auto [made, why] = run_child({"bench", "-q", "--out", out.string()}, one_section);
  ASSERT_EQ(made, 0) << why;
  const std::string before = read_text(out / kManifestFile);
  EXPECT_NE(before.find("\"stability_cfl.png\""), std::string::npos) << before;
  disk.fill(0);
  const auto [code, err] = run_child({"bench", "-q", "--out", out.string()}, one_section);
  EXPECT_EQ(code, 1) << err;
  EXPECT_EQ(err.rfind("shockgas: run failed: ", 0), 0u) << err;
  EXPECT_NE(err.find("No space left on device"), std::string::npos) << err;
  EXPECT_NE(err.find("(the results in the output directory are as they were)"), std::string::npos) << err;
  EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
  EXPECT_EQ(read_text(out / kManifestFile), before);
  const auto [checked, said] = run_child({"info", out.string()});
  EXPECT_EQ(checked, 0) << said;
  EXPECT_TRUE(leftovers(out).empty()) << leftovers(out).front();
}

// `shockgas tail` on a disk that is full (finding: tail_phi.csv cut mid-number,
// tail_runs.csv silently short of a row, and the message said "bench"): the
// earlier study stays whole, and the message names the file in the output
// directory.
TEST(FullDisk, ATailOnAFullDiskLeavesTheEarlierStudyWhole) {
  SmallDisk disk("fulldisk-tail", "1m");
  REQUIRE_MOUNTED(disk);
  const fs::path out = disk.dir() / "t";
  const std::vector<std::string> args = {"tail", "-q",      "--N",   "1000",  "--realizations",
                                         "2",    "--times", "10,20", "--out", out.string()};
  ASSERT_EQ(run_child(args).first, 0);
  const std::string before = read_text(out / "manifest.json");
  disk.fill(0);
  // The tail estimates its disk before any work (resources.cpp): a full disk is
  // refused at once, as bad input (exit 2), naming the room it needs and has.
  const auto [code, err] = run_child(args);
  EXPECT_EQ(code, 2) << err;
  EXPECT_NE(err.find("free"), std::string::npos) << err;
  EXPECT_EQ(err.find("bench"), std::string::npos) << err;
  EXPECT_EQ(err.find(".tmp-"), std::string::npos) << err;
  EXPECT_EQ(read_text(out / "manifest.json"), before);
  EXPECT_EQ(differences_of(check_listed_files(out, *read_manifest(out), "")), "");
  EXPECT_TRUE(leftovers(out).empty()) << leftovers(out).front();
}

}  // namespace
}  // namespace shockgas::app
