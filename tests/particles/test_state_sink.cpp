// The states to be written, handed to a sink in chunks (StateSink): the same
// bodies, in the same order, as RunResult holds without one.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "shockgas/core/initial_condition.hpp"
#include "shockgas/particles/simulate.hpp"

namespace shockgas::particles {
namespace {

// The state, and the largest chunk it came in.
Bodies collect(const StateReader& state, std::size_t& largest) {
  Bodies b;
  state.read([&](const double* x, const double* v, const double* m, std::size_t count) {
    largest = std::max(largest, count);
    for (std::size_t k = 0; k < count; ++k) b.push_back(x[k], v[k], m[k]);
  });
  EXPECT_EQ(b.size(), state.size());
  return b;
}

void expect_same_bodies(const Bodies& a, const Bodies& b) {
  EXPECT_EQ(a.x, b.x);
  EXPECT_EQ(a.v, b.v);
  EXPECT_EQ(a.m, b.m);
}

void expect_sink_gets_the_result_states(Geometry geometry, double r, double delta) {
  InitialParams ip;
  ip.N = 5000;
  ip.positions = Positions::random;
  ip.seed = 12;
  ParticleParams p;
  p.r = r;
  p.delta = delta;
  p.geometry = geometry;
  p.t_end = 400.0;
  p.snapshots = {300.0, 7.0};  // the sink numbers them in ascending order
  const RunResult kept = simulate(ip, 0, p);
  ASSERT_EQ(kept.snapshots.size(), 2u);

  std::vector<Bodies> snapshots(2);
  std::vector<double> times(2);
  Bodies final_state;
  double final_time = 0;
  std::size_t largest = 0;
  StateSink sink;
  sink.snapshot = [&](std::size_t k, double t, const StateReader& s) {
    snapshots.at(k) = collect(s, largest), times[k] = t;
  };
  sink.final_state = [&](double t, const StateReader& s) {
    final_state = collect(s, largest), final_time = t;
  };
  const RunResult streamed = simulate(ip, 0, p, {}, &sink);

  EXPECT_TRUE(streamed.final_state.x.empty());
  EXPECT_TRUE(streamed.snapshots.empty());
  EXPECT_LE(largest, 1024u);  // in chunks, not whole
  EXPECT_EQ(streamed.series.T, kept.series.T);
  EXPECT_EQ(final_time, kept.stop.time);
  expect_same_bodies(final_state, kept.final_state);
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_EQ(times[k], kept.snapshots[k].t);
    expect_same_bodies(snapshots[k], kept.snapshots[k].bodies);
  }
}

TEST(StateSink, RingStatesFromTheSeam) { expect_sink_gets_the_result_states(Geometry::ring, 0.9, 1e-2); }
TEST(StateSink, LineStates) { expect_sink_gets_the_result_states(Geometry::line, 0.9, 1e-2); }
TEST(StateSink, MergedStates) { expect_sink_gets_the_result_states(Geometry::ring, 0.0, 0.0); }

}  // namespace
}  // namespace shockgas::particles
