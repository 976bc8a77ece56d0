#pragma once
// A run killed with SIGKILL anywhere leaves either the complete previous
// results or the complete new ones, never a mix, and the next run clears what
// it left (findings: a failed run mixed old and new files; SIGKILL left
// result.h5.partial-PID, which no later run cleared). The points are named by
// the fault-injection hook (SHOCKGAS_FAULT, shockgas/app/files/fault.hpp); then
// seeded random times. Each kill costs three runs of the command (the old
// results, the killed run, the run after it): test_run_faults.cpp kills at some
// of the points, test_run_faults_slow.cpp (label slow) at all of them.
#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "child_run.hpp"
#include "run_dir_checks.hpp"
#include "two_runs.hpp"

namespace shockgas::app::testing {

// A point of the hook, and which results the directory holds after a kill there.
struct KillPoint {
  std::string fault;
  const char* holds;
};

// Every point the hook names on a run's way, in the order a run passes them.
inline const std::vector<KillPoint> kEveryKillPoint = {
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

// alpha's complete results in out; beta (with the test's plotting script)
// about to replace them.
inline TwoRuns faults_setup(const std::string& name) { return alpha_done(fresh_dir(name), 0.3); }

inline std::vector<std::string> run_beta(const TwoRuns& s) {
  return {"run", s.b.string(), "--out", s.out.string(), "-q", "--force"};
}

// Whatever happened, out holds one whole run: alpha's or beta's.
inline std::string whole_old_or_new(const fs::path& out) {
  const std::string old_one = whole_run(out, "alpha");
  if (old_one.empty()) return "";
  const std::string new_one = whole_run(out, "beta");
  return new_one.empty() ? "" : "neither whole: " + old_one + "; " + new_one;
}

// After a kill: one whole run in out; the next run succeeds, leaves beta whole
// and nothing beside it.
inline void expect_recovers(const TwoRuns& s, const std::string& context) {
  EXPECT_EQ(whole_old_or_new(s.out), "") << context;
  const auto [code, err] = run_child(run_beta(s), with_env({{"SHOCKGAS_PLOT_SCRIPT", s.script.string()}}));
  EXPECT_EQ(code, 0) << context << "\n" << err;
  EXPECT_EQ(whole_run(s.out, "beta"), "") << context;
  EXPECT_TRUE(leftovers(s.out).empty()) << context << ": " << leftovers(s.out).front();
}

// Whether a process whose command line names `script` is alive (/proc/*/cmdline).
inline bool runs_script(const fs::path& script) {
  for (const auto& entry : fs::directory_iterator("/proc")) {
    const std::string name = entry.path().filename().string();
    if (name.find_first_not_of("0123456789") != std::string::npos) continue;
    std::ifstream in(entry.path() / "cmdline");
    const std::string cmdline((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (cmdline.find(script.string()) != std::string::npos) return true;
  }
  return false;
}

// The plotting process dies with a killed shockgas. Its pid, once the script
// has written it (on a loaded machine the kill may come while Python still
// starts; a plotter that lives on writes it later).
inline void expect_no_plotter_outlives(const TwoRuns& s) {
  std::string pid_text;
  for (int i = 0; i < 500 && pid_text.empty(); ++i) {
    if (fs::exists(s.root / "plotter.pid")) pid_text = read_text(s.root / "plotter.pid");
    if (pid_text.empty()) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  if (pid_text.empty()) {
    EXPECT_FALSE(runs_script(s.script)) << "a plotting process outlived a killed shockgas";
    return;
  }
  const pid_t plotter = std::stoi(pid_text);
  for (int i = 0; i < 500 && process_alive(plotter); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  EXPECT_FALSE(process_alive(plotter)) << "the plotting process outlived a killed shockgas";
}

// beta killed by the hook at point p over alpha's results in a directory of its own.
inline void expect_one_whole_run_after_a_kill_at(const KillPoint& p, const std::string& dir_name) {
  const TwoRuns s = faults_setup(dir_name);
  Child run(run_beta(s),
            with_env({{"SHOCKGAS_FAULT", p.fault}, {"SHOCKGAS_PLOT_SCRIPT", s.script.string()}}));
  run.wait();
  ASSERT_EQ(run.signal(), SIGKILL) << p.fault << ": the point was not reached\n" << run.err();
  EXPECT_EQ(whole_run(s.out, p.holds), "") << p.fault;
  if (p.fault.rfind("plot", 0) == 0) expect_no_plotter_outlives(s);
  expect_recovers(s, p.fault);
}

// beta killed `kills` times at seeded random times over the whole run, each
// time over alpha's results. The span is one measured run of the scene; the
// times are the first `kills` draws of one sequence, so fewer kills are a
// prefix of more.
inline void expect_one_whole_run_after_random_kills(int kills, const std::string& dir_name) {
  const TwoRuns s = faults_setup(dir_name);
  const auto start = std::chrono::steady_clock::now();
  ASSERT_EQ(run_child(run_beta(s), with_env({{"SHOCKGAS_PLOT_SCRIPT", s.script.string()}})).first, 0);
  const double span = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::mt19937 rng(2024);
  std::uniform_real_distribution<double> when(0.0, span);
  for (int k = 0; k < kills; ++k) {
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

}  // namespace shockgas::app::testing
