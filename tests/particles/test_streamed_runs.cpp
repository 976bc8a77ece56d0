// Runs from an initial condition that holds no bodies (InitialCondition::Keep::stream):
// the engine and the hull draw realization 0 in chunks, with the same results
// to the bit as from the held bodies, and the hull then holds no copy of them.
#include <gtest/gtest.h>
#include <malloc.h>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <new>

#include "shockgas/core/initial_condition.hpp"
#include "shockgas/core/initial_stream.hpp"
#include "shockgas/particles/simulate.hpp"

// Live heap bytes of this test program and their peak (operator new and
// delete; the engine's own large arrays bypass them, the hull's do not).
namespace {
std::atomic<std::size_t> g_live{0}, g_peak{0};
void* noted(void* p) noexcept {
  if (!p) return p;
  const std::size_t now = g_live += malloc_usable_size(p);
  for (std::size_t peak = g_peak; now > peak && !g_peak.compare_exchange_weak(peak, now);) {
  }
  return p;
}
void* counted(void* p) {
  if (!p) throw std::bad_alloc();
  return noted(p);
}
void uncounted(void* p) {
  if (p) g_live -= malloc_usable_size(p);
  std::free(p);
}
}  // namespace
void* operator new(std::size_t n) { return counted(std::malloc(n ? n : 1)); }
void* operator new[](std::size_t n) { return counted(std::malloc(n ? n : 1)); }
void operator delete(void* p) noexcept { uncounted(p); }
void operator delete[](void* p) noexcept { uncounted(p); }
void operator delete(void* p, std::size_t) noexcept { uncounted(p); }
void operator delete[](void* p, std::size_t) noexcept { uncounted(p); }
// The nothrow forms too (std::stable_sort's buffer): each allocation must meet
// the delete of the same family, or the sanitizer sees new paired with free.
void* operator new(std::size_t n, const std::nothrow_t&) noexcept { return noted(std::malloc(n ? n : 1)); }
void* operator new[](std::size_t n, const std::nothrow_t& tag) noexcept { return operator new(n, tag); }
void operator delete(void* p, const std::nothrow_t&) noexcept { uncounted(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { uncounted(p); }

namespace shockgas::particles {
namespace {

using Keep = InitialCondition::Keep;

InitialParams gas(std::size_t N, Positions positions = Positions::random) {
  InitialParams ip;
  ip.N = N;
  ip.positions = positions;
  ip.seed = 7;
  return ip;
}

void expect_same_run(const RunResult& a, const RunResult& b) {
  EXPECT_EQ(a.series.T, b.series.T);
  EXPECT_EQ(a.series.n_clusters, b.series.n_clusters);
  EXPECT_EQ(a.series.dissipated, b.series.dissipated);
  EXPECT_EQ(a.collisions, b.collisions);
  EXPECT_EQ(a.final_state.x, b.final_state.x);
  EXPECT_EQ(a.final_state.v, b.final_state.v);
  EXPECT_EQ(a.final_state.m, b.final_state.m);
  ASSERT_EQ(a.snapshots.size(), b.snapshots.size());
  for (std::size_t k = 0; k < a.snapshots.size(); ++k)
    EXPECT_EQ(a.snapshots[k].bodies.x, b.snapshots[k].bodies.x);
}

TEST(StreamedRuns, EngineAndHullGiveTheHeldBodiesResults) {
  const InitialParams ip = gas(4000);
  const InitialCondition held(ip, Keep::bodies), streamed(ip, Keep::stream);
  ASSERT_FALSE(streamed.holds_bodies());
  for (ParticleSolver solver : {ParticleSolver::events, ParticleSolver::hull})
    for (Geometry geometry : {Geometry::ring, Geometry::line}) {
      SCOPED_TRACE(std::string(name_of(solver)) + " " + std::string(name_of(geometry)));
      ParticleParams p;
      p.solver = solver;
      p.r = solver == ParticleSolver::hull ? 0.0 : 0.9;
      p.geometry = geometry;
      p.t_end = 200;
      p.snapshots = {5.0};
      p.threads = 1;
      for (std::uint64_t k : {0u, 2u}) expect_same_run(simulate(streamed, k, p), simulate(held, k, p));
    }
}

// A run's initial temperature is that of the bodies it drew, summed as they
// were drawn (TemperatureSums): the same bits from held bodies, and as
// initial_temperature(). The bound against temperature()'s two passes: both
// sums' rounding, about N eps each, N = 4000: 2e-12.
TEST(StreamedRuns, TheInitialTemperatureIsThatOfTheBodiesDrawn) {
  const InitialParams ip = gas(4000);
  const InitialCondition held(ip, Keep::bodies), streamed(ip, Keep::stream);
  for (ParticleSolver solver : {ParticleSolver::events, ParticleSolver::hull}) {
    SCOPED_TRACE(name_of(solver));
    ParticleParams p;
    p.solver = solver;
    p.r = solver == ParticleSolver::hull ? 0.0 : 0.9;
    p.t_end = 10;
    p.threads = 1;
    for (std::uint64_t k : {0u, 2u}) {
      const double exact = temperature(make_initial_bodies(ip, k));
      const RunResult drawn = simulate(streamed, k, p);
      ASSERT_TRUE(drawn.initial_temperature.has_value());
      EXPECT_NEAR(*drawn.initial_temperature, exact, 2e-12 * exact);
      EXPECT_NE(*drawn.initial_temperature, temperature(make_initial_bodies(ip, k + 1)));
    }
    const RunResult whole = simulate(held, 0, p);
    ASSERT_TRUE(whole.initial_temperature.has_value());
    EXPECT_EQ(*whole.initial_temperature, *simulate(streamed, 0, p).initial_temperature);
    EXPECT_EQ(*whole.initial_temperature, initial_temperature(streamed, 0));
  }
}

// The hull keeps 20 bytes per run (its arrays are sized for N runs), nothing of
// the bodies it was built from: the largest live heap during a run is within
// 20 N bytes plus a fixed 2 MiB; a copy of the bodies would add 24 N (24 MB
// here). Lattice positions: random ones are held sorted (8 N) while drawn.
TEST(StreamedRuns, TheHullHoldsNoCopyOfTheBodies) {
  const std::size_t N = 1000000;
  const InitialCondition streamed(gas(N, Positions::lattice), Keep::stream);
  ParticleParams p;
  p.solver = ParticleSolver::hull;
  p.r = 0;
  p.t_end = 100;
  p.samples = 3;
  p.threads = 1;
  p.final_clusters = ClusterRecord::never;  // a record it is asked for, not a copy (resources.cpp counts it)
  const StateSink discard;                  // as run_realization runs the other realizations
  const std::size_t before = g_live;
  g_peak = before;
  const RunResult r = simulate(streamed, 0, p, {}, &discard);
  EXPECT_EQ(r.series.size(), 3u);
  const std::size_t held = g_peak - before;
  EXPECT_LE(held, 20 * N + (std::size_t{2} << 20)) << held / static_cast<double>(N) << " bytes per body";
}

}  // namespace
}  // namespace shockgas::particles
