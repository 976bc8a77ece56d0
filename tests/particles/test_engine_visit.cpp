// The engine's bodies visited by chain position (EventEngine::for_each_body
// with a range, what ChainView::visit of a range reads): the visit of
// positions [begin, end) is that slice of the whole visit, to the bit, with and
// without merged bodies (whose slots the linked engine skips).
#include <gtest/gtest.h>

#include <cstddef>
#include <vector>

#include "engine_fixtures.hpp"
#include "shockgas/core/initial_condition.hpp"
#include "shockgas/particles/run_watch.hpp"
#include "shockgas/particles/window_scheduler.hpp"

namespace shockgas::particles::detail {
namespace {

struct Visited {
  std::vector<std::size_t> index;
  std::vector<double> x, v, m;
  bool operator==(const Visited&) const = default;
};

template <bool Linked>
Visited visit(const EventEngine<Linked>& e, double t, std::size_t begin, std::size_t end) {
  Visited out;
  e.for_each_body(
      t,
      [&](std::size_t i, double x, double v, double m) {
        out.index.push_back(i), out.x.push_back(x), out.v.push_back(v), out.m.push_back(m);
      },
      begin, end);
  return out;
}

Visited slice(const Visited& all, std::size_t begin, std::size_t end) {
  auto cut = [&](const auto& a) { return std::vector(a.begin() + begin, a.begin() + end); };
  return {cut(all.index), cut(all.x), cut(all.v), cut(all.m)};
}

// A gas of n bodies run to t under `rule` on the windowed engine, one thread.
template <bool Linked>
EventEngine<Linked> run_gas(std::size_t n, const CollisionRule& rule, double t) {
  InitialParams ip;
  ip.N = n;
  ip.positions = Positions::random;
  ip.velocities = Velocities::uniform;
  ip.seed = 41;
  EventEngine<Linked> e = engine_of<Linked>(make_initial_bodies(ip), true, rule);
  const ParticleParams unlimited;
  const ProgressCallback no_progress;
  RunWatch watch{unlimited, no_progress};
  WindowScheduler<Linked> scheduler(e, 1, 0.0);
  EXPECT_EQ(scheduler.run_until(t, watch), EngineStop::reached);
  return e;
}

template <bool Linked>
void expect_ranges_are_slices(const EventEngine<Linked>& e) {
  const double t = e.now();
  const std::size_t n = e.alive();
  const Visited all = visit(e, t, 0, n);
  ASSERT_EQ(all.x.size(), n);
  EXPECT_EQ(visit(e, t, 0, static_cast<std::size_t>(-1)), all);  // the default end: to the last body
  for (const auto& [begin, end] : {std::pair{std::size_t{0}, n},
                                   {0, 1},
                                   {n - 1, n},
                                   {n / 3, n},
                                   {0, n / 3},
                                   {n / 3, 2 * n / 3},
                                   {n, n},
                                   {n / 2, n / 2}})
    EXPECT_EQ(visit(e, t, begin, end), slice(all, begin, end)) << "positions " << begin << " to " << end;
}

TEST(EngineVisit, ARangeOfPositionsIsThatSliceOfTheWholeVisit) {
  const EventEngine<false> e = run_gas<false>(5000, {0.9, 1e-2, false}, 50.0);
  EXPECT_EQ(e.alive(), 5000u);
  expect_ranges_are_slices(e);
}

TEST(EngineVisit, ARangeOfPositionsSkipsTheMergedBodies) {
  // r = 0: every collision merges; most of the 5000 bodies are gone by t = 50.
  const EventEngine<true> e = run_gas<true>(5000, {0.0, 0.0, false}, 50.0);
  ASSERT_LT(e.alive(), 2500u);
  expect_ranges_are_slices(e);
}

}  // namespace
}  // namespace shockgas::particles::detail
