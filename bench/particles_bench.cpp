// Collisions per second of the particle engine against the priority-queue
// baseline (particles_baseline.hpp), in the same run, at N = 10^4, 10^5, 10^6:
// the reference configuration (ring, L = N, lattice positions, velocities uniform on
// [-1, 1], r = 0.9, delta = 10^-2). The engine runs twice: as shipped
// (particles.schedule = "auto": time windows over stretches of the chain) and on
// its global event queue (schedule = "global"). All start from the same state and
// run the same number of collisions (10^7 by default; a windowed run stops at the
// end of the window that reaches it); the engine is timed whole (set-up, event
// loop, final state), as a run would be.
//
//   particles_bench [--csv=FILE] [--collisions=C] [benchmark flags]
//
// Writes FILE (default particles_bench.csv): N, the rates of the engine, of its
// global queue and of the baseline [collisions per CPU second and per wall
// second], and the ratios engine / baseline.
#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdlib>
#include <cstring>
#include <ctime>
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

// Wall-clock and process CPU time: on a shared machine the CPU time is the
// fairer measure (the process is descheduled while others run).
struct Rate {
  double collisions = 0;
  double seconds = 0;      // wall clock
  double cpu_seconds = 0;  // process CPU time
  double per_second() const { return seconds > 0 ? collisions / seconds : 0; }
  double per_cpu_second() const { return cpu_seconds > 0 ? collisions / cpu_seconds : 0; }
};

struct Stopwatch {
  std::chrono::steady_clock::time_point wall = std::chrono::steady_clock::now();
  std::clock_t cpu = std::clock();
  double wall_seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - wall).count();
  }
  double cpu_seconds() const { return static_cast<double>(std::clock() - cpu) / CLOCKS_PER_SEC; }
};
std::map<std::pair<std::string, std::size_t>, Rate> g_rates;

shockgas::Bodies initial_bodies(std::size_t n) {
  shockgas::InitialParams ip;
  ip.N = n;
  ip.seed = 2026;
  return shockgas::make_initial_bodies(ip);
}

void record(benchmark::State& state, const std::string& engine, std::size_t n, double collisions,
            const Stopwatch& watch) {
  Rate& r = g_rates[{engine, n}];
  r.collisions += collisions;
  r.seconds += watch.wall_seconds();
  r.cpu_seconds += watch.cpu_seconds();
  state.counters["collisions_per_cpu_second"] = benchmark::Counter(r.per_cpu_second());
}

void run_engine(benchmark::State& state, const std::string& schedule, const std::string& name) {
  const std::size_t n = static_cast<std::size_t>(state.range(0));
  const shockgas::Bodies b = initial_bodies(n);
  shockgas::particles::ParticleParams p;
  p.schedule = shockgas::parse_enum<shockgas::particles::Schedule>(schedule, "particles.schedule");
  p.r = kR;
  p.delta = kDelta;
  p.t_end = 1e12;
  p.samples = 1;
  p.clusters = false;
  p.max_collisions = g_collisions;
  for (auto _ : state) {
    const Stopwatch watch;
    const auto out = shockgas::particles::simulate(b, static_cast<double>(n), p);
    benchmark::DoNotOptimize(out.final_state.v.data());
    record(state, name, n, static_cast<double>(out.collisions), watch);
  }
}
void BM_Engine(benchmark::State& state) { run_engine(state, "auto", "engine"); }
void BM_EngineGlobalQueue(benchmark::State& state) { run_engine(state, "global", "global"); }

void BM_Baseline(benchmark::State& state) {
  const std::size_t n = static_cast<std::size_t>(state.range(0));
  const shockgas::Bodies b = initial_bodies(n);
  for (auto _ : state) {
    const Stopwatch watch;
    shockgas::bench::BaselineEngine engine(b, static_cast<double>(n), kR, kDelta);
    const std::uint64_t done = engine.run(g_collisions);
    benchmark::DoNotOptimize(engine.momentum());
    record(state, "baseline", n, static_cast<double>(done), watch);
  }
}

constexpr std::size_t kSizes[] = {10'000, 100'000, 1'000'000};
void sizes(benchmark::internal::Benchmark* b) {
  for (std::size_t n : kSizes) b->Arg(static_cast<std::int64_t>(n));
  b->Unit(benchmark::kMillisecond);
}
BENCHMARK(BM_Engine)->Apply(sizes)->Iterations(2);
BENCHMARK(BM_EngineGlobalQueue)->Apply(sizes)->Iterations(1);
BENCHMARK(BM_Baseline)->Apply(sizes)->Iterations(1);

void write_csv(const std::string& path) {
  std::ofstream out(path);
  out << "N,collisions,engine_per_cpu_s,global_queue_per_cpu_s,baseline_per_cpu_s,ratio_cpu,"
         "engine_per_wall_s,global_queue_per_wall_s,baseline_per_wall_s,ratio_wall\n";
  for (std::size_t n : kSizes) {
    const Rate& e = g_rates[{"engine", n}];
    const Rate& q = g_rates[{"global", n}];
    const Rate& b = g_rates[{"baseline", n}];
    if (e.collisions == 0 && q.collisions == 0 && b.collisions == 0) continue;
    auto ratio = [](double x, double y) { return y > 0 ? x / y : 0.0; };
    out << n << ',' << g_collisions << ',' << e.per_cpu_second() << ',' << q.per_cpu_second() << ','
        << b.per_cpu_second() << ',' << ratio(e.per_cpu_second(), b.per_cpu_second()) << ',' << e.per_second()
        << ',' << q.per_second() << ',' << b.per_second() << ',' << ratio(e.per_second(), b.per_second())
        << '\n';
    std::cout << "N = " << n << ": engine " << e.per_cpu_second() / 1e6 << " M/cpu-s ("
              << e.per_second() / 1e6 << " M/wall-s), global queue " << q.per_cpu_second() / 1e6
              << " M/cpu-s, baseline " << b.per_cpu_second() / 1e6 << " M/cpu-s (" << b.per_second() / 1e6
              << " M/wall-s), ratio " << ratio(e.per_cpu_second(), b.per_cpu_second()) << " (cpu), "
              << ratio(e.per_second(), b.per_second()) << " (wall)\n";
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
