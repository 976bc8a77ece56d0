// Collisions per second of the particle engine against the priority-queue
// baseline (particles_baseline.hpp), in the same run, at N = 10^4, 10^5, 10^6:
// the configuration (ring, L = N, lattice positions, velocities uniform on
// [-1, 1], r = 0.9, delta = 10^-2). Both engines start from the same state and
// run the same number of collisions (10^7 by default); the engine is timed
// whole (set-up, event loop, final state), as a run would be.
//
//   particles_bench [--csv=FILE] [--collisions=C] [benchmark flags]
//
// Writes FILE (default particles_bench.csv): N, engine and baseline rates
// [collisions/s] and their ratio.
#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <map>
#include <string>

#include "particles_baseline.hpp"
#include "shockgas/core/initial_condition.hpp"
#include "shockgas/particles/simulate.hpp"

namespace {

constexpr double kR = 0.9;
constexpr double kDelta = 1e-2;
std::uint64_t g_collisions = 10'000'000;

struct Rate {
  double collisions = 0;
  double seconds = 0;
  double per_second() const { return seconds > 0 ? collisions / seconds : 0; }
};
std::map<std::pair<std::string, std::size_t>, Rate> g_rates;

shockgas::Bodies initial_bodies(std::size_t n) {
  shockgas::InitialParams ip;
  ip.N = n;
  ip.seed = 2026;
  return shockgas::make_initial_bodies(ip);
}

void record(benchmark::State& state, const std::string& engine, std::size_t n, double collisions,
            double seconds) {
  Rate& r = g_rates[{engine, n}];
  r.collisions += collisions;
  r.seconds += seconds;
  state.counters["collisions_per_second"] = benchmark::Counter(collisions / seconds);
}

void BM_Engine(benchmark::State& state) {
  const std::size_t n = static_cast<std::size_t>(state.range(0));
  const shockgas::Bodies b = initial_bodies(n);
  shockgas::particles::ParticleParams p;
  p.r = kR;
  p.delta = kDelta;
  p.t_end = 1e12;
  p.samples = 1;
  p.clusters = false;
  p.max_collisions = g_collisions;
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    const auto out = shockgas::particles::simulate(b, static_cast<double>(n), p);
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    benchmark::DoNotOptimize(out.final_state.v.data());
    record(state, "engine", n, static_cast<double>(out.collisions), s);
  }
}

void BM_Baseline(benchmark::State& state) {
  const std::size_t n = static_cast<std::size_t>(state.range(0));
  const shockgas::Bodies b = initial_bodies(n);
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    shockgas::bench::BaselineEngine engine(b, static_cast<double>(n), kR, kDelta);
    const std::uint64_t done = engine.run(g_collisions);
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    benchmark::DoNotOptimize(engine.momentum());
    record(state, "baseline", n, static_cast<double>(done), s);
  }
}

BENCHMARK(BM_Engine)->Arg(10'000)->Arg(100'000)->Arg(1'000'000)->Unit(benchmark::kMillisecond)->Iterations(2);
BENCHMARK(BM_Baseline)
    ->Arg(10'000)
    ->Arg(100'000)
    ->Arg(1'000'000)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

void write_csv(const std::string& path) {
  std::ofstream out(path);
  out << "N,collisions,engine_collisions_per_s,baseline_collisions_per_s,ratio\n";
  for (std::size_t n : {10'000, 100'000, 1'000'000}) {
    const double e = g_rates[{"engine", n}].per_second();
    const double b = g_rates[{"baseline", n}].per_second();
    if (e == 0 && b == 0) continue;
    out << n << ',' << g_collisions << ',' << e << ',' << b << ',' << (b > 0 ? e / b : 0) << '\n';
    std::cout << "N = " << n << ": engine " << e / 1e6 << " M/s, baseline " << b / 1e6 << " M/s, ratio "
              << (b > 0 ? e / b : 0) << '\n';
  }
  std::cout << "wrote " << path << '\n';
}

}  // namespace

int main(int argc, char** argv) {
  std::string csv = "particles_bench.csv";
  int kept = 1;
  for (int i = 1; i < argc; ++i) {
    if (std::strncmp(argv[i], "--csv=", 6) == 0) {
      csv = argv[i] + 6;
    } else if (std::strncmp(argv[i], "--collisions=", 13) == 0) {
      g_collisions = std::strtoull(argv[i] + 13, nullptr, 10);
    } else {
      argv[kept++] = argv[i];
    }
  }
  argc = kept;
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  write_csv(csv);
  return 0;
}
