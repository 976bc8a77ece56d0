// Progress on stderr after the particles (finding: the default scene said
// nothing for 5 s after its particles while the continuum was solved, the
// results written and the plots drawn): each phase of a run longer than a
// second has one line, "NAME ... 1.2 s", in the order the run goes through
// them; --quiet prints none.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <numeric>
#include <regex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "child_run.hpp"
#include "run_dir_checks.hpp"
#include "shockgas/app/run/progress_bar.hpp"

namespace shockgas::app {
namespace {

using namespace testing;
using namespace std::chrono_literals;

// The names of the finished phases said, in order: "NAME ... 1.2 s", or
// "NAME: 1.2 s" after a solver's bar of its own (on a slow host) broke its line.
std::vector<std::string> phases_said(const std::string& err) {
  static const std::regex finished(R"(^(.*?)(?: \.\.\. |: )[0-9]+\.[0-9] s$)");
  std::vector<std::string> names;
  std::istringstream in(err);
  std::smatch m;
  for (std::string line; std::getline(in, line);)
    if (std::regex_match(line, m, finished)) names.push_back(m[1].str());
  return names;
}

struct ProgressRun {
  fs::path root, scene, out, script;
};

// alpha (particles, two solvers, a comparison) and a plotting script that
// draws one picture and says nothing.
ProgressRun setup(const std::string& name, double plot_seconds) {
  ProgressRun s;
  s.root = fresh_dir(name);
  s.scene = s.root / "alpha.toml";
  s.out = s.root / "D";
  write_text(s.scene, kSceneA);
  s.script = fake_plot_script(s.root, plot_seconds);
  return s;
}

// The run is held at its first write of result.h5, before the particles, until
// it has run for more than a second: from then on every phase is said as it
// starts, in order, and completed with its time.
TEST(Progress, EachPhaseAfterTheParticlesHasOneLineWithItsTimeInOrder) {
  const ProgressRun s = setup("progress-order", 0);
  Child run(
      {"run", s.scene.string(), "--out", s.out.string()},
      with_env({{"SHOCKGAS_FAULT", "write:result.h5:1:stop"}, {"SHOCKGAS_PLOT_SCRIPT", s.script.string()}}));
  ASSERT_TRUE(run.wait_stopped()) << run.err();
  std::this_thread::sleep_for(1200ms);  // past the silent first second of the process
  kill(run.pid(), SIGCONT);
  ASSERT_EQ(run.wait(), 0) << run.err();
  const std::vector<std::string> expected{"particles: analysis, writing result.h5",
                                          "continuum: solving hopf_lax, godunov",
                                          "comparison: clusters against the shocks of hopf_lax",
                                          "writing result.h5, summary.json",
                                          "plots",
                                          "writing report.md, report.html, manifest.json",
                                          "syncing, moving into " + s.out.string()};
  EXPECT_EQ(phases_said(run.err()), expected) << run.err();
  EXPECT_EQ(whole_run(s.out, "alpha"), "");
}

// A phase that starts within the first second and lasts beyond it is said
// when the second is over (the plotting script sleeps 1.5 s).
TEST(Progress, APhaseThatOutlastsTheFirstSecondIsSaid) {
  const ProgressRun s = setup("progress-first-second", 1.5);
  const auto [code, err] = run_child({"run", s.scene.string(), "--out", s.out.string()},
                                     with_env({{"SHOCKGAS_PLOT_SCRIPT", s.script.string()}}));
  ASSERT_EQ(code, 0) << err;
  const std::vector<std::string> said = phases_said(err);
  const std::vector<std::string> from_plots{"plots", "writing report.md, report.html, manifest.json",
                                            "syncing, moving into " + s.out.string()};
  ASSERT_GE(said.size(), from_plots.size()) << err;
  EXPECT_EQ(std::vector<std::string>(said.end() - 3, said.end()), from_plots) << err;
}

// The particles' last line says 100 % at the end time (finding: the default
// scene's ended at "93%  t = 1e+04": the realizations were polled only while
// some still ran). Held at the first report, past the silent first second.
TEST(Progress, TheParticlesEndAtOneHundredPercent) {
  const ProgressRun s = setup("progress-particles-end", 0);
  Child run({"run", s.scene.string(), "--out", s.out.string(), "--no-plots"},
            with_env({{"SHOCKGAS_FAULT", "compute:1:stop"}}));
  ASSERT_TRUE(run.wait_stopped()) << run.err();
  std::this_thread::sleep_for(1200ms);
  kill(run.pid(), SIGCONT);
  ASSERT_EQ(run.wait(), 0) << run.err();
  std::string last;  // the particles' last line
  std::istringstream in(run.err());
  for (std::string line; std::getline(in, line);)
    if (line.rfind("particles: ", 0) == 0 && line.find('%') != std::string::npos) last = line;
  EXPECT_EQ(last.rfind("particles: 100%  t = 50 ", 0), 0u) << run.err();
}

// --quiet: nothing on stderr, the same run held as long.
TEST(Progress, QuietSaysNothing) {
  const ProgressRun s = setup("progress-quiet", 1.5);
  Child run(
      {"run", s.scene.string(), "--out", s.out.string(), "-q"},
      with_env({{"SHOCKGAS_FAULT", "write:result.h5:1:stop"}, {"SHOCKGAS_PLOT_SCRIPT", s.script.string()}}));
  ASSERT_TRUE(run.wait_stopped()) << run.err();
  std::this_thread::sleep_for(1200ms);
  kill(run.pid(), SIGCONT);
  ASSERT_EQ(run.wait(), 0) << run.err();
  EXPECT_EQ(run.err(), "");
  EXPECT_EQ(whole_run(s.out, "alpha"), "");
}

// report.md gives every phase up to the plots with its wall time, the
// particles' simulation first, also when --quiet says none: the plotting
// script sleeps 1.5 s, so the plots' row holds at least that.
TEST(Progress, ReportGivesEachPhaseWithItsTimeAlsoWhenQuiet) {
  const ProgressRun s = setup("progress-report", 1.5);
  const auto [code, err] = run_child({"run", s.scene.string(), "--out", s.out.string(), "-q"},
                                     with_env({{"SHOCKGAS_PLOT_SCRIPT", s.script.string()}}));
  ASSERT_EQ(code, 0) << err;
  const std::string report = read_text(s.out / "report.md");
  const std::string table = report.substr(report.find("## Time of each phase"));
  std::vector<std::string> phases;
  std::smatch m;
  double plots = 0;
  static const std::regex row(R"(\| ([^|]+) \| ([0-9]+\.[0-9]{2}) s \|)");
  for (auto it = table.cbegin(); std::regex_search(it, table.cend(), m, row); it = m[0].second) {
    phases.push_back(m[1].str());
    if (m[1].str() == "plots") plots = std::stod(m[2].str());
  }
  const std::vector<std::string> expected{"particles: simulation",
                                          "particles: analysis, writing result.h5",
                                          "continuum: solving hopf_lax, godunov",
                                          "comparison: clusters against the shocks of hopf_lax",
                                          "writing result.h5, summary.json",
                                          "plots"};
  EXPECT_EQ(phases, expected) << report;
  EXPECT_GE(plots, 1.5) << report;
}

// stderr of f(), written while it runs (into a file: the bar writes with stdio).
template <class F>
std::string stderr_of(const std::string& name, F f) {
  const fs::path log = fresh_dir(name) / "stderr";
  std::fflush(stderr);
  const int saved = dup(STDERR_FILENO);
  std::FILE* file = std::fopen(log.c_str(), "w");
  EXPECT_NE(file, nullptr);
  dup2(fileno(file), STDERR_FILENO);
  f();
  std::fflush(stderr);
  dup2(saved, STDERR_FILENO);
  close(saved);
  std::fclose(file);
  return read_text(log);
}

// The time left is that of this process's work (finding: a run resumed at
// t = 1323 said "1.54e+03 time units/s" after 1 s, the restored work over this
// process's seconds). As in a resumed run, the first poll says 0 (the workers
// have not yet taken up their checkpoints) and the next one the checkpoint's
// 99.5 %; 0.1 % more follows in at least 1.1 s, so the remaining 0.4 % takes at
// least 4 x 1.1 = 4.4 s (counted from 0, the resumed share would say 0 s).
TEST(Progress, ARunTakenUpAtACheckpointCountsItsRateFromThere) {
  const std::string err = stderr_of("progress-rate", [] {
    ProgressBar bar(true);
    bar.stage("particles");
    bar.update(0, 0);         // the first poll, before the workers took up their checkpoints
    bar.update(0.995, 9950);  // where the checkpoint was
    std::this_thread::sleep_for(1100ms);
    bar.update(0.996, 9960);  // not a terminal: one line per 10 %, the first one now
  });
  std::smatch m;
  ASSERT_TRUE(std::regex_search(err, m, std::regex(R"(particles: 100%.*eta ([0-9]+) s)"))) << err;
  EXPECT_GE(std::stod(m[1].str()), 4.0) << err;  // 4.4 s printed to the second
}

// An ensemble of 8 realizations in a log: each line says which realization of
// 8 is under way and the time left. The scripted clock runs the realizations
// at costs 10 % apart around 1 s (as the same scene's realizations differ by
// their initial states); at 50 % the eta, from the mean rate so far, is within
// 30 % of the time the scripted clock then still takes.
TEST(Progress, ALogSaysWhichRealizationAndAnEtaWithin30PercentAtHalfWay) {
  const std::vector<double> cost = {1.0, 0.9, 1.1, 1.0, 0.95, 1.1, 0.9, 1.05};  // [s] each
  double clock = 0;
  const auto start = ProgressBar::Clock::now();
  const auto scripted = [&] {
    return start +
           std::chrono::duration_cast<ProgressBar::Clock::duration>(std::chrono::duration<double>(clock));
  };
  double remaining_at_half = 0;
  const std::string err = stderr_of("progress-eta", [&] {
    ProgressBar bar(true, {}, scripted);
    bar.stage("particles", cost.size());
    constexpr int kSteps = 20;  // updates per realization
    for (std::size_t k = 0; k < cost.size(); ++k)
      for (int i = 1; i <= kSteps; ++i) {
        clock += cost[k] / kSteps;
        const double fraction = (static_cast<double>(k) + i / static_cast<double>(kSteps)) / 8;
        bar.update(fraction, 0);
        if (fraction == 0.5) remaining_at_half = std::accumulate(cost.begin() + 4, cost.end(), 0.0);
      }
    bar.finish();
  });
  std::smatch m;
  ASSERT_TRUE(std::regex_search(
      err, m, std::regex(R"(particles:  50%  realization 5 of 8  elapsed [0-9.]+ s  eta ([0-9]+) s)")))
      << err;
  EXPECT_NEAR(std::stod(m[1].str()), remaining_at_half, 0.3 * remaining_at_half) << err;
  EXPECT_NE(err.find("realization 8 of 8"), std::string::npos) << err;
}

// A log gives the engine's speed as it is quoted, collisions per second since
// the stage's first progress (simulated time per second falls as the gas
// slows): 8e6 collisions between the scripted seconds 1 and 3 are 4.0 M/s. A
// stage that counts none (a continuum solver) gives no rate on its later lines.
TEST(Progress, ALogGivesTheCollisionsPerSecondSinceTheFirstProgress) {
  double clock = 0;
  const auto start = ProgressBar::Clock::now();
  const auto scripted = [&] {
    return start +
           std::chrono::duration_cast<ProgressBar::Clock::duration>(std::chrono::duration<double>(clock));
  };
  const std::string err = stderr_of("progress-collisions", [&] {
    ProgressBar bar(true, {}, scripted);
    bar.stage("particles");
    clock = 1.0;
    bar.update(0.1, 10, 1'000'000);  // the base: a line for 10 %, no rate yet
    clock = 3.0;
    bar.update(0.5, 50, 9'000'000);
    bar.stage("continuum/godunov");
    clock = 5.0;
    bar.update(0.2, 0.1);  // the base of its rate, were it counting
    clock = 7.0;
    bar.update(0.6, 0.3);
    bar.finish();
  });
  EXPECT_TRUE(std::regex_search(
      err, std::regex(R"(particles:  50%  t = 50  elapsed 3\.0 s  eta [0-9]+ s  4\.0 M collisions/s\n)")))
      << err;
  const auto continuum = err.find("continuum/godunov:");
  ASSERT_NE(continuum, std::string::npos) << err;
  EXPECT_EQ(err.find("collisions/s", continuum), std::string::npos) << err;
}

}  // namespace
}  // namespace shockgas::app
