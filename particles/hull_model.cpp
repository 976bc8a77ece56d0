#include "hull_model.hpp"

#include <algorithm>
#include <chrono>

#include "recorder.hpp"
#include "shockgas/core/sticky_hull.hpp"

namespace shockgas::particles::detail {

namespace {

// The clusters at time t in chain order (by first particle).
std::vector<StickyCluster> hull_state(const Bodies& initial, double L, bool ring, double t) {
  std::vector<StickyCluster> c =
      ring ? sticky_clusters_ring(initial, L, t) : sticky_clusters_line(initial, t);
  const std::size_t n = initial.size();
  for (StickyCluster& k : c) k.first %= n;
  std::sort(c.begin(), c.end(),
            [](const StickyCluster& a, const StickyCluster& b) { return a.first < b.first; });
  return c;
}

auto chain_view(const std::vector<StickyCluster>& s) {
  return make_chain_view(s.size(), [&s](auto&& f) {
    for (const StickyCluster& k : s) f(k.first, k.x, k.v, k.m);
  });
}

Counters hull_counters(std::size_t n, double initial_energy, const std::vector<StickyCluster>& s) {
  double energy = 0;
  for (const StickyCluster& k : s) energy += 0.5 * k.m * k.v * k.v;
  const std::uint64_t merges = n - s.size();
  return {merges, 0, 0, merges, initial_energy - energy};
}

}  // namespace

RunResult simulate_hull(const Bodies& initial, double L, bool ring, const ParticleParams& p) {
  const auto start = std::chrono::steady_clock::now();
  const std::size_t n = initial.size();
  const double energy = kinetic_energy(initial);
  Recorder recorder(p, n, L, ring);
  for (double t = recorder.next_stop(); t != Recorder::done; t = recorder.next_stop()) {
    const std::vector<StickyCluster> s = hull_state(initial, L, ring, t);
    recorder.observe(t, chain_view(s), hull_counters(n, energy, s));
  }
  const std::vector<StickyCluster> final_state = hull_state(initial, L, ring, p.t_end);
  RunResult out = recorder.finish(chain_view(final_state), {StopReason::completed, p.t_end, 0.0},
                                  hull_counters(n, energy, final_state));
  out.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace shockgas::particles::detail
