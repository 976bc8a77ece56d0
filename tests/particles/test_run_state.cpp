// Saving a run in progress and continuing from the save (run_state.hpp): the
// run that saved goes on unchanged, and a run resumed from the save ends with
// the uninterrupted run's results, every field bit for bit (RunResult but its
// wall time), on the ring and the line, with bounces (r = 0.9, delta > 0) and
// merges (r = 0, sticky), in time windows and on the global queue, with saves
// inside a plan, at a plan's end and on the global queue, for several seeds and
// on another number of threads than the saving run.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <string>

#include "shockgas/core/error.hpp"
#include "shockgas/core/initial_condition.hpp"
#include "shockgas/core/interrupt.hpp"
#include "shockgas/particles/run_state.hpp"
#include "shockgas/particles/simulate.hpp"

namespace shockgas::particles {
namespace {

class MemoryWriter : public RunStateWriter {
 public:
  void write(const void* data, std::size_t bytes) override {
    bytes_.append(static_cast<const char*>(data), bytes);
  }
  std::string bytes_;
};

class MemoryReader : public RunStateReader {
 public:
  explicit MemoryReader(std::string bytes) : bytes_(std::move(bytes)) {}
  void read(void* data, std::size_t bytes) override {
    if (bytes > remaining()) throw RunError("read past the end of the state");
    std::memcpy(data, bytes_.data() + at_, bytes);
    at_ += bytes;
  }
  std::size_t remaining() const override { return bytes_.size() - at_; }

 private:
  std::string bytes_;
  std::size_t at_ = 0;
};

// Saves once, at the safe point number `at` (1 = the first); counts the safe points.
class SaveAt : public RunSaves {
 public:
  explicit SaveAt(int at) : at_(at) {}
  bool due() override { return ++points_ == at_; }
  void save(double t, double, const std::function<void(RunStateWriter&)>& write) override {
    MemoryWriter out;
    write(out);
    state = std::move(out.bytes_);
    time = t;
  }
  std::string state;
  double time = -1;
  int points_ = 0;

 private:
  int at_;
};

struct Case {
  const char* name;
  double r, delta;
  Subthreshold sub;
  Schedule schedule;
  Geometry geometry;
};

InitialParams gas(std::size_t n, std::uint64_t seed) {
  InitialParams ip;
  ip.N = n;
  ip.positions = Positions::random;
  ip.seed = seed;
  return ip;
}

// Every record the run can take: samples with cluster counts, a histogram or
// parts-measured samples, snapshots and (small N) a space-time record.
ParticleParams params(const Case& c, std::size_t threads, bool histogram) {
  ParticleParams p;
  p.r = c.r;
  p.delta = c.delta;
  p.subthreshold = c.sub;
  p.schedule = c.schedule;
  p.geometry = c.geometry;
  p.t_end = 40;
  p.samples = 25;
  p.clusters = true;
  p.snapshots = {3, 20};
  p.histogram_bins = histogram ? 8 : 0;
  p.threads = threads;
  return p;
}

void expect_same(const RunResult& a, const RunResult& b) {
  TimeSeries sa = a.series, sb = b.series;
  std::vector<std::vector<double>> ca, cb;
  sa.for_each_column([&](const char*, std::vector<double>& v) { ca.push_back(v); });
  sb.for_each_column([&](const char*, std::vector<double>& v) { cb.push_back(v); });
  EXPECT_EQ(ca, cb);
  for (auto column : {&Bodies::x, &Bodies::v, &Bodies::m})
    EXPECT_EQ(a.final_state.*column, b.final_state.*column);
  ASSERT_EQ(a.snapshots.size(), b.snapshots.size());
  for (std::size_t k = 0; k < a.snapshots.size(); ++k) {
    EXPECT_EQ(a.snapshots[k].t, b.snapshots[k].t);
    for (auto column : {&Bodies::x, &Bodies::v, &Bodies::m})
      EXPECT_EQ(a.snapshots[k].bodies.*column, b.snapshots[k].bodies.*column);
  }
  EXPECT_EQ(a.histogram.t, b.histogram.t);
  EXPECT_EQ(a.histogram.density, b.histogram.density);
  EXPECT_EQ(a.spacetime.labels, b.spacetime.labels);
  EXPECT_EQ(a.spacetime.t, b.spacetime.t);
  EXPECT_EQ(a.spacetime.x, b.spacetime.x);
  EXPECT_EQ(a.stop.reason, b.stop.reason);
  EXPECT_EQ(a.stop.time, b.stop.time);
  EXPECT_EQ(a.stop.position, b.stop.position);
  EXPECT_EQ(a.collisions, b.collisions);
  EXPECT_EQ(a.schedule.order, b.schedule.order);
  EXPECT_EQ(a.schedule.why_global, b.schedule.why_global);
}

// Saved at the safe point a `share` of the way through the run's safe points,
// by a run on 2 threads; resumed on 1.
void expect_resumed_run_is_the_run(const Case& c, std::uint64_t seed, double share, bool histogram,
                                   std::size_t n) {
  const InitialParams ip = gas(n, seed);
  SaveAt count(0);
  const RunResult straight = simulate(ip, 0, params(c, 2, histogram), {}, nullptr, {&count, nullptr});
  ASSERT_EQ(straight.stop.reason, StopReason::completed);
  ASSERT_GE(count.points_, 3) << c.name << ": too few safe points to save inside the run";
  const int at = std::clamp(static_cast<int>(share * count.points_), 1, count.points_ - 1);
  SCOPED_TRACE(std::string(c.name) + " seed " + std::to_string(seed) + " saved at safe point " +
               std::to_string(at) + " of " + std::to_string(count.points_) +
               (histogram ? " with a histogram" : ""));
  SaveAt saves(at);
  const RunResult saving = simulate(ip, 0, params(c, 2, histogram), {}, nullptr, {&saves, nullptr});
  ASSERT_FALSE(saves.state.empty()) << "the run has fewer than " << at << " safe points";
  EXPECT_GT(saves.time, 0);
  EXPECT_LT(saves.time, straight.stop.time);
  expect_same(saving, straight);  // saving changed nothing
  MemoryReader in(saves.state);
  const RunResult resumed = simulate(ip, 0, params(c, 1, histogram), {}, nullptr, {nullptr, &in});
  expect_same(resumed, straight);
}

const Case kBounces{"ring, r = 0.9", 0.9, 1e-2, Subthreshold::elastic, Schedule::windows, Geometry::ring};
const Case kBouncesLine{"line, r = 0.9", 0.9, 1e-2, Subthreshold::elastic, Schedule::windows, Geometry::line};
const Case kBouncesGlobal{"ring, r = 0.9, global", 0.9,           1e-2, Subthreshold::elastic,
                          Schedule::global,        Geometry::ring};
const Case kSticky{"ring, sticky r = 0", 0.0, 1e-2, Subthreshold::sticky, Schedule::windows, Geometry::ring};
const Case kStickyLine{"line, sticky r = 0", 0.0,           1e-2, Subthreshold::sticky,
                       Schedule::windows,    Geometry::line};
const Case kStickyGlobal{
    "line, sticky r = 0, global", 0.0, 1e-2, Subthreshold::sticky, Schedule::global, Geometry::line};

TEST(RunState, ResumedInWindowsIsTheUninterruptedRun) {
  for (const Case& c : {kBounces, kBouncesLine, kSticky, kStickyLine})
    for (std::uint64_t seed : {3u, 11u})
      for (double share : {0.0, 0.4, 0.9}) expect_resumed_run_is_the_run(c, seed, share, false, 20000);
}

TEST(RunState, ResumedWithAHistogramIsTheUninterruptedRun) {
  for (const Case& c : {kBounces, kSticky}) expect_resumed_run_is_the_run(c, 5, 0.5, true, 20000);
}

TEST(RunState, ResumedOnTheGlobalQueueIsTheUninterruptedRun) {
  for (const Case& c : {kBouncesGlobal, kStickyGlobal})
    for (std::uint64_t seed : {3u, 11u})
      for (double share : {0.0, 0.6})  // merges: at most N - 1, so N = 2e5 for a few check points of 2^14
        expect_resumed_run_is_the_run(c, seed, share, false, c.r == 0 ? 200000 : 20000);
}

// A run that leaves the windows for the global queue (thin plans: an open
// line spreads out), saved before, around and after the switch.
TEST(RunState, ResumedAcrossTheSwitchToTheGlobalQueueIsTheUninterruptedRun) {
  Case line = kBouncesLine;
  line.name = "line, r = 0.9, to t = 1e4";
  const InitialParams ip = gas(4096, 3);
  ParticleParams p = params(line, 2, false);
  p.t_end = 1e4;
  const RunResult straight = simulate(ip, 0, p);
  ASSERT_EQ(straight.schedule.order, "windows, then global") << straight.schedule.why_global;
  SaveAt count(0);
  simulate(ip, 0, p, {}, nullptr, {&count, nullptr});
  ParticleParams one = p;
  one.threads = 1;
  for (double share : {0.2, 0.5, 0.8, 0.95}) {
    SaveAt saves(std::clamp(static_cast<int>(share * count.points_), 1, count.points_ - 1));
    simulate(ip, 0, p, {}, nullptr, {&saves, nullptr});
    ASSERT_FALSE(saves.state.empty());
    MemoryReader in(saves.state);
    expect_same(simulate(ip, 0, one, {}, nullptr, {nullptr, &in}), straight);
  }
}

// N = 2000 with a space-time record; windows need N >= 1024.
TEST(RunState, ResumedWithASpaceTimeRecordIsTheUninterruptedRun) {
  for (const Case& c : {kBounces, kSticky}) {
    const InitialParams ip = gas(2000, 7);
    ParticleParams p = params(c, 2, false);
    p.spacetime = true;
    p.spacetime_frames = 9;
    const RunResult straight = simulate(ip, 0, p);
    SaveAt saves(3);
    simulate(ip, 0, p, {}, nullptr, {&saves, nullptr});
    ASSERT_FALSE(saves.state.empty());
    MemoryReader in(saves.state);
    expect_same(simulate(ip, 0, p, {}, nullptr, {nullptr, &in}), straight);
  }
}

// Asks for a checkpoint (as a signal would) at safe point `at`, after that
// point's save decision, and saves only when asked.
class AskAt : public SaveAt {
 public:
  using SaveAt::SaveAt;
  bool due() override {
    if (SaveAt::due()) request_interrupt(InterruptMode::checkpoint);
    return false;
  }
};

// A checkpoint request with saves: the run saves at its next safe point, or
// inside the sub-window it is in, and throws Interrupted; resumed, it ends as
// the uninterrupted run. With one sample (at t_end) the sub-windows are whole
// plans; those of the bounces at N = 2e4 (~10^5 collisions) are cut short at
// the first look at the watch inside them (every 2^13 rounds of a member).
TEST(RunState, CheckpointRequestSavesThenStops) {
  for (const Case& c : {kBounces, kBouncesGlobal, kSticky})
    for (std::size_t samples : {std::size_t{25}, std::size_t{1}}) {
      SCOPED_TRACE(std::string(c.name) + ", samples " + std::to_string(samples));
      clear_interrupt();
      const InitialParams ip = gas(c.r == 0 ? 200000 : 20000, 13);  // merges: fewer collisions
      ParticleParams p = params(c, 2, false);
      p.samples = samples;
      const RunResult straight = simulate(ip, 0, p);
      const int at = 3;
      AskAt saves(at);
      EXPECT_THROW(simulate(ip, 0, p, {}, nullptr, {&saves, nullptr}), Interrupted);
      clear_interrupt();
      ASSERT_FALSE(saves.state.empty());
      EXPECT_EQ(saves.points_, at) << "saved and stopped before any further safe point was asked";
      MemoryReader in(saves.state);
      expect_same(simulate(ip, 0, p, {}, nullptr, {nullptr, &in}), straight);
    }
}

// A state resumed in another run, or cut short, is refused (RunError), never run.
TEST(RunState, ForeignOrTruncatedStateIsRefused) {
  const ParticleParams p = params(kBounces, 1, false);
  SaveAt saves(2);
  simulate(gas(20000, 3), 0, p, {}, nullptr, {&saves, nullptr});
  ASSERT_FALSE(saves.state.empty());
  MemoryReader other_n(saves.state);
  EXPECT_THROW(simulate(gas(30000, 3), 0, p, {}, nullptr, {nullptr, &other_n}), RunError);
  MemoryReader other_rule(saves.state);
  EXPECT_THROW(simulate(gas(20000, 3), 0, params(kSticky, 1, false), {}, nullptr, {nullptr, &other_rule}),
               RunError);
  MemoryReader global(saves.state);
  EXPECT_THROW(simulate(gas(20000, 3), 0, params(kBouncesGlobal, 1, false), {}, nullptr, {nullptr, &global}),
               RunError);
  for (std::size_t keep : {std::size_t{5}, saves.state.size() / 2, saves.state.size() - 1}) {
    MemoryReader cut(saves.state.substr(0, keep));
    EXPECT_THROW(simulate(gas(20000, 3), 0, p, {}, nullptr, {nullptr, &cut}), RunError) << keep << " bytes";
  }
}

}  // namespace
}  // namespace shockgas::particles
