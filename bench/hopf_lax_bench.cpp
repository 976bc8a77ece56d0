// Speed of the exact inviscid solvers (targets: "Hopf-Lax >= 1e7 points/s; 1e7
// points in about a second"). Points per second of CPU time (items_per_second).
//
//  * BM_StickyLine/N: sticky_clusters_line on N lattice bodies, velocities
//    uniform on [-1, 1], t = 10 (about a fifth of the bodies left as clusters).
//  * BM_StickyRing/N: sticky_clusters_ring on the same bodies (three unrolled periods).
//  * BM_HopfLaxField/n: the whole exact solve for v0 = 0.5 + sin 2 pi x at
//    t = 0.5 (after the shock) with n samples of Psi0 per period (n/4 cells):
//    quadrature, hull, refinement at every cell edge, shocks.
//  * BM_HopfLaxBodies/N: solve_hopf_lax on the same N bodies as point masses on
//    the ring (the sticky hull plus the deposit on N/4 cells).
//  * Baseline BM_TextbookHull/N: Andrew's monotone chain on the cumulative points
//    (M_k, S_k) after std::sort, with cross products: the direct way to the
//    same hull as BM_StickyLine.
//  * Baseline BM_BruteForceHopfLax/n: every cell edge minimised over all n
//    samples, O(n^2 / 4); compare with BM_HopfLaxField at the same n.
// The ratios are printed at the end of the run.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <string>
#include <vector>

#include "shockgas/continuum/hopf_lax.hpp"
#include "shockgas/core/random.hpp"
#include "shockgas/core/sticky_hull.hpp"

namespace {

constexpr double kStickyTime = 10.0;
constexpr double kFieldTime = 0.5;

shockgas::Bodies lattice_bodies(std::size_t n) {
  shockgas::Rng rng(2024);
  shockgas::Bodies b;
  b.reserve(n);
  for (std::size_t i = 0; i < n; ++i) b.push_back(static_cast<double>(i), rng.uniform(-1.0, 1.0), 1.0);
  return b;
}

shockgas::InitialField sine_field() {
  shockgas::InitialField f;
  f.v0 = [](double x) { return 0.5 + std::sin(2 * std::numbers::pi * x); };
  return f;
}

void BM_StickyLine(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const shockgas::Bodies b = lattice_bodies(n);
  for (auto _ : state) benchmark::DoNotOptimize(shockgas::sticky_clusters_line(b, kStickyTime));
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * n));
}

void BM_StickyRing(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const shockgas::Bodies b = lattice_bodies(n);
  for (auto _ : state)
    benchmark::DoNotOptimize(shockgas::sticky_clusters_ring(b, static_cast<double>(n), kStickyTime));
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * n));
}

void BM_HopfLaxField(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const shockgas::InitialField f = sine_field();
  shockgas::continuum::HopfLaxOptions o;
  o.samples_per_cell = 4;
  o.min_samples = 16;
  for (auto _ : state) benchmark::DoNotOptimize(shockgas::continuum::solve_hopf_lax(f, n / 4, kFieldTime, o));
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * n));
}

void BM_HopfLaxBodies(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  shockgas::InitialField f;
  f.length = static_cast<double>(n);
  f.bodies = lattice_bodies(n);
  for (auto _ : state) benchmark::DoNotOptimize(shockgas::continuum::solve_hopf_lax(f, n / 4, kStickyTime));
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * n));
}

// Lower hull by the textbook monotone chain; returns the number of vertices.
std::size_t textbook_hull(const shockgas::Bodies& b, double t) {
  struct P {
    double x, y;
  };
  std::vector<P> p(b.size() + 1);
  p[0] = {0, 0};
  for (std::size_t k = 0; k < b.size(); ++k)
    p[k + 1] = {p[k].x + b.m[k], p[k].y + b.m[k] * (b.x[k] + t * b.v[k])};
  std::sort(p.begin(), p.end(),
            [](const P& a, const P& c) { return a.x < c.x || (a.x == c.x && a.y < c.y); });
  std::vector<P> h;
  for (const P& q : p) {
    while (h.size() >= 2) {
      const P& a = h[h.size() - 2];
      const P& o = h.back();
      if ((o.x - a.x) * (q.y - a.y) - (o.y - a.y) * (q.x - a.x) > 0) break;
      h.pop_back();
    }
    h.push_back(q);
  }
  return h.size();
}

void BM_TextbookHull(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const shockgas::Bodies b = lattice_bodies(n);
  for (auto _ : state) benchmark::DoNotOptimize(textbook_hull(b, kStickyTime));
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * n));
}

// Psi(x) = min_j [(x - q_j)^2 / 2t + Psi0(q_j)] at every cell edge by direct
// search over the n samples of one period and its neighbours.
void BM_BruteForceHopfLax(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const std::size_t cells = n / 4;
  const double h = 1.0 / static_cast<double>(n);
  std::vector<double> q(3 * n), psi(3 * n);
  for (std::size_t j = 0; j < 3 * n; ++j) {
    q[j] = (static_cast<double>(j) - static_cast<double>(n)) * h;
    psi[j] = (1 - std::cos(2 * std::numbers::pi * q[j])) / (2 * std::numbers::pi);
  }
  std::vector<double> out(cells + 1);
  for (auto _ : state) {
    for (std::size_t i = 0; i <= cells; ++i) {
      const double y = static_cast<double>(i) / static_cast<double>(cells);
      double best = INFINITY;
      for (std::size_t j = 0; j < 3 * n; ++j)
        best = std::min(best, (y - q[j]) * (y - q[j]) / (2 * kFieldTime) + psi[j]);
      out[i] = best;
    }
    benchmark::DoNotOptimize(out.data());
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * n));
}

// Console output plus a record of points/s per benchmark, for the ratios.
class RatioReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& r : runs) {
      auto it = r.counters.find("items_per_second");
      if (it != r.counters.end()) rate_[r.benchmark_name()] = it->second.value;
    }
  }
  void ratio(const std::string& fast, const std::string& slow) const {
    const auto a = rate_.find(fast), b = rate_.find(slow);
    if (a == rate_.end() || b == rate_.end() || b->second <= 0) return;
    std::printf("ratio %s / %s = %.1f  (%.3g vs %.3g points/s)\n", fast.c_str(), slow.c_str(),
                a->second / b->second, a->second, b->second);
  }

 private:
  std::map<std::string, double> rate_;
};

}  // namespace

BENCHMARK(BM_StickyLine)->Arg(100000)->Arg(1000000)->Arg(10000000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_StickyRing)->Arg(100000)->Arg(1000000)->Arg(10000000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_HopfLaxBodies)->Arg(100000)->Arg(1000000)->Arg(10000000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_TextbookHull)->Arg(1000000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_HopfLaxField)
    ->Arg(16384)
    ->Arg(100000)
    ->Arg(1000000)
    ->Arg(10000000)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_BruteForceHopfLax)->Arg(16384)->Unit(benchmark::kMillisecond);

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  RatioReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  reporter.ratio("BM_StickyLine/1000000", "BM_TextbookHull/1000000");
  reporter.ratio("BM_HopfLaxField/16384", "BM_BruteForceHopfLax/16384");
  benchmark::Shutdown();
  return 0;
}
