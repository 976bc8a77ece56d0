#include "hull_model.hpp"

#include <algorithm>
#include <chrono>

#include "recorder.hpp"
#include "shockgas/core/sticky_hull.hpp"

namespace shockgas::particles::detail {

namespace {

// The clusters at time t in chain order (by first particle).
ChainState hull_state(const Bodies& initial, double L, bool ring, double t) {
  std::vector<StickyCluster> c =
      ring ? sticky_clusters_ring(initial, L, t) : sticky_clusters_line(initial, t);
  const std::size_t n = initial.size();
  for (StickyCluster& k : c) k.first %= n;
  std::sort(c.begin(), c.end(),
            [](const StickyCluster& a, const StickyCluster& b) { return a.first < b.first; });
  ChainState s;
  for (const StickyCluster& k : c) s.push_back(k.first, k.x, k.v, k.m);
  return s;
}

Counters hull_counters(std::size_t n, double initial_energy, const ChainState& s) {
  double energy = 0;
  for (std::size_t b = 0; b < s.v.size(); ++b) energy += 0.5 * s.m[b] * s.v[b] * s.v[b];
  const std::uint64_t merges = n - s.x.size();
  return {merges, 0, 0, merges, initial_energy - energy};
}

}  // namespace

RunResult simulate_hull(const Bodies& initial, double L, bool ring, const ParticleParams& p) {
  const auto start = std::chrono::steady_clock::now();
  const std::size_t n = initial.size();
  const double energy = kinetic_energy(initial);
  Recorder recorder(p, n, L, ring);
  for (double t = recorder.next_stop(); t != Recorder::done; t = recorder.next_stop()) {
    const ChainState s = hull_state(initial, L, ring, t);
    recorder.observe(t, s, hull_counters(n, energy, s));
  }
  const ChainState final_state = hull_state(initial, L, ring, p.t_end);
  RunResult out = recorder.finish(final_state, {StopReason::completed, p.t_end, 0.0},
                                  hull_counters(n, energy, final_state));
  out.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace shockgas::particles::detail
