// A run killed with SIGKILL anywhere leaves either the complete previous
// results or the complete new ones, never a mix, and the next run clears what
// it left (findings: a failed run mixed old and new files; SIGKILL left
// result.h5.partial-PID, which no later run cleared). The points are named by
// the fault-injection hook (SHOCKGAS_FAULT, shockgas/app/files/fault.hpp); then a few seeded
// random times.
#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <thread>

#include "child_run.hpp"
#include "run_dir_checks.hpp"
#include "two_runs.hpp"

namespace shockgas::app {
namespace {

using namespace testing;

using Scenario = TwoRuns;

// alpha's complete results in out; beta (with the test's plotting script)
// about to replace them.
Scenario setup(const std::string& name) { return alpha_done(fresh_dir(name), 0.3); }

std::vector<std::string> run_beta(const Scenario& s) {
  return {"run", s.b.string(), "--out", s.out.string(), "-q", "--force"};
}

// Whatever happened, out holds one whole run: alpha's or beta's.
std::string whole_old_or_new(const fs::path& out) {
  const std::string old_one = whole_run(out, "alpha");
  if (old_one.empty()) return "";
  const std::string new_one = whole_run(out, "beta");
  return new_one.empty() ? "" : "neither whole: " + old_one + "; " + new_one;
}

// After a kill: one whole run in out; the next run succeeds, leaves beta whole
// and nothing beside it.
void expect_recovers(const Scenario& s, const std::string& context) {
  EXPECT_EQ(whole_old_or_new(s.out), "") << context;
  const auto [code, err] = run_child(run_beta(s), with_env({{"SHOCKGAS_PLOT_SCRIPT", s.script.string()}}));
  EXPECT_EQ(code, 0) << context << "\n" << err;
  EXPECT_EQ(whole_run(s.out, "beta"), "") << context;
  EXPECT_TRUE(leftovers(s.out).empty()) << context << ": " << leftovers(s.out).front();
}

// Whether a process whose command line names `script` is alive (/proc/*/cmdline).
bool runs_script(const fs::path& script) {
  for (const auto& entry : fs::directory_iterator("/proc")) {
    const std::string name = entry.path().filename().string();
    if (name.find_first_not_of("0123456789") != std::string::npos) continue;
    std::ifstream in(entry.path() / "cmdline");
    const std::string cmdline((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (cmdline.find(script.string()) != std::string::npos) return true;
  }
  return false;
}

struct Point {
  std::string fault;
  const char* holds;  // which results the directory holds after the kill there
};

TEST(RunFaults, AKillAtEachNamedPointLeavesOneWholeRun) {
  const std::vector<Point> points = {
      {"compute", "alpha"},
      {"write:result.h5:1", "alpha"},
      {"write:result.h5:20", "alpha"},
      {"write:summary.json", "alpha"},
      {"write:report.md", "alpha"},
      {"plot:10", "alpha"},
      {"write:manifest.json", "alpha"},
      {"swap", "alpha"},
      {"swapped", "beta"},
  };
  for (const auto& p : points) {
    const Scenario s = setup("faults-" + std::to_string(&p - points.data()));
    Child run(run_beta(s),
              with_env({{"SHOCKGAS_FAULT", p.fault}, {"SHOCKGAS_PLOT_SCRIPT", s.script.string()}}));
    run.wait();
    ASSERT_EQ(run.signal(), SIGKILL) << p.fault << ": the point was not reached\n" << run.err();
    EXPECT_EQ(whole_run(s.out, p.holds), "") << p.fault;
    if (p.fault.rfind("plot", 0) == 0) {  // the plotting process dies with shockgas
      // Its pid, once the script has written it (on a loaded machine the kill may
      // come while Python still starts; a plotter that lives on writes it later).
      std::string pid_text;
      for (int i = 0; i < 500 && pid_text.empty(); ++i) {
        if (fs::exists(s.root / "plotter.pid")) pid_text = read_text(s.root / "plotter.pid");
        if (pid_text.empty()) std::this_thread::sleep_for(std::chrono::milliseconds(10));
      }
      if (!pid_text.empty()) {
        const pid_t plotter = std::stoi(pid_text);
        for (int i = 0; i < 500 && process_alive(plotter); ++i)
          std::this_thread::sleep_for(std::chrono::milliseconds(10));
        EXPECT_FALSE(process_alive(plotter)) << "the plotting process outlived a killed shockgas";
      } else {
        EXPECT_FALSE(runs_script(s.script)) << "a plotting process outlived a killed shockgas";
      }
    }
    expect_recovers(s, p.fault);
  }
}

// Random times over the whole run (seeded): the same guarantee wherever the
// kill falls. The span is one measured run of the scene.
TEST(RunFaults, AKillAtRandomTimesLeavesOneWholeRun) {
  const Scenario s = setup("faults-random");
  const auto start = std::chrono::steady_clock::now();
  ASSERT_EQ(run_child(run_beta(s), with_env({{"SHOCKGAS_PLOT_SCRIPT", s.script.string()}})).first, 0);
  const double span = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::mt19937 rng(2024);
  std::uniform_real_distribution<double> when(0.0, span);
  for (int k = 0; k < 6; ++k) {
    ASSERT_EQ(run_child({"run", s.a.string(), "--out", s.out.string(), "-q", "--no-plots", "--force"}).first,
              0);
    const double t = when(rng);
    Child run(run_beta(s), with_env({{"SHOCKGAS_PLOT_SCRIPT", s.script.string()}}));
    std::this_thread::sleep_for(std::chrono::duration<double>(t));
    kill(run.pid(), SIGKILL);
    run.wait();
    expect_recovers(s, "killed after " + std::to_string(t) + " s");
  }
}

}  // namespace
}  // namespace shockgas::app
