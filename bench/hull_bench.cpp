// The exact sticky hull against a plain pool-adjacent-violators pass, and the
// observables of one sample, per particle:
//
//  * plain_pav: isotonic regression of y_i = x_i + t v_i with weights m_i, the
//    textbook stack of blocks (mean, weight) pooled by weighted means: the
//    least any hull must do (it yields neither velocities nor the partition);
//  * hull_line, hull_ring: StickyHull::line / ring from the bodies (validation,
//    clusters with centre of mass, velocity, mass and members);
//  * hull_advance, hull_scratch: 40 log-spaced samples in [1, t], each advanced
//    from the previous sample's clusters, or each built from the bodies;
//  * observables_T, observables_default, observables_all: one sample of the
//    recorder over an engine-like chain (T only; T and cluster count, today's
//    defaults; and the histogram too).
//
// Bodies: ring / line of N, L = N, lattice, velocities uniform on [-1, 1]. Time
// is process CPU time, the median of the iterations; bytes per particle are the
// resident memory the result holds (its touched pages; input not counted), read
// from /proc/self/statm.
//
//   hull_bench [--csv=FILE] [benchmark flags]      (FILE default hull_bench.csv)
#include <benchmark/benchmark.h>
#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include <algorithm>
#include <cmath>
#include <ctime>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <string>
#include <tuple>

#include "csv_main.hpp"
#include "plain_pav.hpp"
#include "shockgas/core/initial_condition.hpp"
#include "shockgas/core/sticky_hull.hpp"
#include "shockgas/particles/recorder.hpp"
#include "shockgas/particles/simulate.hpp"

namespace {

using shockgas::Bodies;
using shockgas::StickyHull;

constexpr std::size_t kSamples = 40;

struct Result {
  double ns = 0, bytes = 0;  // per particle (per sample for the sampled measures)
};
std::map<std::tuple<std::string, std::size_t, double>, Result> g_results;

double cpu_seconds() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

// The median of the iterations' times: one run slowed by the shared machine does not move it.
double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

// Resident bytes of the process (0 where /proc is missing).
double resident_bytes() {
  std::ifstream statm("/proc/self/statm");
  double pages = 0, resident = 0;
  if (!(statm >> pages >> resident)) return 0;
  return resident * 4096.0;
}

const Bodies& bodies(std::size_t n) {
  static std::size_t cached = 0;
  static Bodies b;
  if (cached != n) {
    shockgas::InitialParams ip;
    ip.N = n;
    ip.seed = 2026;
    b = shockgas::make_initial_bodies(ip);
    cached = n;
  }
  return b;
}

// The plain pass: blocks (mean of y, weight) on a stack; returns the block count.
// Pushed body by body, as the command's baseline is.
struct PlainPav {
  shockgas::bench::PlainPav stack;
  std::size_t blocks = 0;
  PlainPav(const Bodies& b, double t) : stack(b.size()) {
    for (std::size_t i = 0; i < b.size(); ++i) stack.push(b.x[i] + t * b.v[i], b.m[i]);
    blocks = stack.blocks();
  }
};

// Times `make` (which returns the object holding the result) per particle; its
// resident bytes per particle are read once, with the result alive.
template <class Make>
void measure(benchmark::State& state, const std::string& name, double per, Make&& make) {
  const std::size_t n = static_cast<std::size_t>(state.range(0));
  const double t = static_cast<double>(state.range(1));
  bodies(n);
  Result& r = g_results[{name, n, t}];
  std::vector<double> seconds;
  for (auto _ : state) {
    const double start = cpu_seconds();
    auto result = make(n, t);
    seconds.push_back(cpu_seconds() - start);
    benchmark::DoNotOptimize(result);
  }
  const double before = resident_bytes();
  {
    const auto held = make(n, t);
    r.bytes = (resident_bytes() - before) / static_cast<double>(n);
    benchmark::DoNotOptimize(held);
  }
  r.ns = 1e9 * median(seconds) / static_cast<double>(n) / per;
  state.counters["ns_per_particle"] = r.ns;
  state.counters["bytes_per_particle"] = r.bytes;
}

void BM_PlainPav(benchmark::State& state) {
  measure(state, "plain_pav", 1, [](std::size_t n, double t) { return PlainPav(bodies(n), t); });
}
void BM_HullLine(benchmark::State& state) {
  measure(state, "hull_line", 1, [](std::size_t n, double t) { return StickyHull::line(bodies(n), t); });
}
void BM_HullRing(benchmark::State& state) {
  measure(state, "hull_ring", 1,
          [](std::size_t n, double t) { return StickyHull::ring(bodies(n), static_cast<double>(n), t); });
}

// 40 log-spaced sample times in [1, t].
std::vector<double> samples(double t) { return shockgas::particles::detail::sample_times(t, kSamples); }

void BM_HullAdvance(benchmark::State& state) {
  measure(state, "hull_advance", kSamples, [](std::size_t n, double t) {
    const std::vector<double> times = samples(t);
    StickyHull h = StickyHull::ring(bodies(n), static_cast<double>(n), times.front());
    for (double tk : times) h.advance(tk);
    return h;
  });
}
void BM_HullScratch(benchmark::State& state) {
  measure(state, "hull_scratch", kSamples, [](std::size_t n, double t) {
    std::size_t clusters = 0;
    for (double tk : samples(t)) clusters += StickyHull::ring(bodies(n), static_cast<double>(n), tk).size();
    return clusters;
  });
}

// An engine-like state: the engine's bodies (x at local time, v) after a run of
// 10^5 particles (r = 0.9, delta = 10^-2) to t = 100, repeated around a ring of N.
struct EngineLikeChain {
  struct Body {
    double x, v, t;
  };
  std::vector<Body> body;
  double L;
  double t = 0;  // the state's time; every sample reads it there
  explicit EngineLikeChain(std::size_t n) : L(static_cast<double>(n)) {
    static const Bodies tile = [] {
      shockgas::particles::ParticleParams p;
      p.t_end = 100;
      p.samples = 1;
      p.clusters = false;
      return shockgas::particles::simulate(bodies(100'000), 1e5, p).final_state;
    }();
    body.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t copy = i / tile.size();  // the tile's copy body i is in, each 1e5 further on
      body[i] = {tile.x[i % tile.size()] + 1e5 * static_cast<double>(copy), tile.v[i % tile.size()], 0.0};
    }
  }
};

// One recorder sample per particle: kSamples samples of the same state, timed.
void observables(benchmark::State& state, const std::string& name, bool clusters, std::size_t bins) {
  namespace detail = shockgas::particles::detail;
  const std::size_t n = static_cast<std::size_t>(state.range(0));
  const EngineLikeChain chain(n);
  shockgas::particles::ParticleParams p;
  p.t_end = static_cast<double>(state.range(1));
  p.samples = kSamples;
  p.clusters = clusters;
  p.histogram_bins = bins;
  std::vector<double> seconds;
  for (auto _ : state) {
    const double start = cpu_seconds();
    detail::Recorder recorder(p, n, chain.L, true, 1.0);  // unit masses
    for (double s = recorder.next_stop(); s != detail::Recorder::done; s = recorder.next_stop()) {
      const auto view = detail::make_chain_view(n, [&](auto&& f, std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) {
          const EngineLikeChain::Body& b = chain.body[i];
          f(i, b.x + b.v * (chain.t - b.t), b.v, 1.0);  // lazy position, as the engine's
        }
      });
      recorder.observe(s, view, detail::Counters{});
    }
    seconds.push_back(cpu_seconds() - start);
  }
  Result& r = g_results[{name, n, p.t_end}];
  r.ns = 1e9 * median(seconds) / static_cast<double>(n) / kSamples;
  state.counters["ns_per_particle"] = r.ns;
}
void BM_ObservablesT(benchmark::State& state) { observables(state, "observables_T", false, 0); }
void BM_ObservablesDefault(benchmark::State& state) { observables(state, "observables_default", true, 0); }
void BM_ObservablesAll(benchmark::State& state) { observables(state, "observables_all", true, 60); }

constexpr std::int64_t kSizes[] = {100'000, 1'000'000, 10'000'000};
void passes(benchmark::internal::Benchmark* b) {
  for (std::int64_t n : kSizes)
    for (std::int64_t t : {1, 1000}) b->Args({n, t});
  b->Unit(benchmark::kMillisecond)->Iterations(5);
}
void sampled(benchmark::internal::Benchmark* b) {
  for (std::int64_t n : kSizes) b->Args({n, 1000});
  b->Unit(benchmark::kMillisecond)->Iterations(3);
}
BENCHMARK(BM_PlainPav)->Apply(passes);
BENCHMARK(BM_HullLine)->Apply(passes);
BENCHMARK(BM_HullRing)->Apply(passes);
BENCHMARK(BM_HullAdvance)->Apply(sampled);
BENCHMARK(BM_HullScratch)->Apply(sampled);
BENCHMARK(BM_ObservablesT)->Apply(sampled);
BENCHMARK(BM_ObservablesDefault)->Apply(sampled);
BENCHMARK(BM_ObservablesAll)->Apply(sampled);

// Long format: measure, N, t, ns and bytes per particle, and for the hull the
// time ratio to the plain pass at the same N and t (0 where none).
void write_csv(const std::string& path) {
  std::ofstream out(path);
  out << "measure,N,t,ns_per_particle,bytes_per_particle,ratio_to_plain_pav\n";
  for (const auto& [key, r] : g_results) {
    const auto& [name, n, t] = key;
    const auto plain = g_results.find({"plain_pav", n, t});
    const bool hull = name.starts_with("hull");
    const double ratio =
        hull && plain != g_results.end() && plain->second.ns > 0 ? r.ns / plain->second.ns : 0.0;
    out << name << ',' << n << ',' << t << ',' << r.ns << ',' << r.bytes << ',' << ratio << '\n';
    std::cout << name << " N = " << n << " t = " << t << ": " << r.ns << " ns, " << r.bytes
              << " bytes per particle"
              << (ratio > 0 ? ", " + std::to_string(ratio) + " x plain PAV" : std::string()) << '\n';
  }
  std::cout << "wrote " << path << '\n';
}

}  // namespace

int main(int argc, char** argv) {
#if defined(__GLIBC__)
  // Every large block its own mapping, so that its touched pages are what it adds to the resident set.
  mallopt(M_MMAP_THRESHOLD, 128 * 1024);
#endif
  return shockgas::bench::run_with_csv(argc, argv, "hull_bench.csv", write_csv);
}
