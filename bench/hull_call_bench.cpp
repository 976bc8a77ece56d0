// The exact sticky gas as one call from C++: sticky_clusters_ring(bodies, L, t),
// the clusters sorted by x, the work behind shockgas.hull in Python.
// bench/python_hull_bench.py times that Python call on the same bodies and
// reports the ratio of the two: the cost of calling from Python (copying the
// arrays in, the columns out).
//
// Bodies: a lattice ring of N, L = N, velocities uniform on [-1, 1], seed 2026
// (the scene keys initial.N and initial.seed; realization 0). The output is
// allocated by each call. The iteration count follows wall time; the CPU time
// per call is what python_hull_bench.py compares (the machine may be shared).
//
//   hull_call_bench [benchmark flags]   e.g. --benchmark_format=json --benchmark_repetitions=9
#include <benchmark/benchmark.h>

#include <cstdint>

#include "shockgas/core/initial_condition.hpp"
#include "shockgas/core/sticky_hull.hpp"

namespace {

constexpr std::uint64_t kSeed = 2026;

void BM_StickyClustersRing(benchmark::State& state) {
  shockgas::InitialParams ip;
  ip.N = static_cast<std::size_t>(state.range(0));
  ip.seed = kSeed;
  const shockgas::Bodies bodies = shockgas::make_initial_bodies(ip);
  const double L = static_cast<double>(ip.N), t = static_cast<double>(state.range(1));
  std::size_t clusters = 0;
  for (auto _ : state) {
    const auto c = shockgas::sticky_clusters_ring(bodies, L, t);
    clusters = c.size();
    benchmark::DoNotOptimize(c.data());
  }
  state.counters["clusters"] = static_cast<double>(clusters);
}

BENCHMARK(BM_StickyClustersRing)
    ->Args({1000000, 1})
    ->Args({1000000, 1000})
    ->ArgNames({"N", "t"})
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
