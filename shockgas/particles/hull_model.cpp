#include "shockgas/particles/hull_model.hpp"

#include <optional>

#include "shockgas/core/initial_stream.hpp"
#include "shockgas/core/sticky_hull.hpp"
#include "shockgas/particles/recorder.hpp"
#include "shockgas/particles/run_watch.hpp"

namespace shockgas::particles::detail {

namespace {

// The hull's clusters as the recorder reads them, in chain order (x unrolled on a ring).
auto chain_view(const StickyHull& hull) {
  return make_chain_view(hull.size(), [&hull](auto&& f, std::size_t begin, std::size_t end) {
    std::size_t k = 0;  // chain position; a cluster's first particle needs the ones before
    hull.for_each([&](const StickyCluster& c) {
      if (k >= begin && k < end) f(c.first, c.x, c.v, c.m);
      ++k;
    });
  });
}

Counters hull_counters(double initial_energy, const StickyHull& hull) {
  double energy = 0;
  hull.for_each([&](const StickyCluster& c) { energy += 0.5 * c.m * c.v * c.v; });
  const std::uint64_t merges = hull.bodies() - hull.size();
  return {merges, 0, 0, merges, initial_energy - energy};
}

// The run from `build(t)`, the hull of the n initial bodies of mean mass
// mean_mass at t, called once; `energy()` their kinetic energy, read after it.
template <class Build, class Energy>
RunResult run_hull(std::size_t n, double mean_mass, Build&& build, Energy&& energy, double L, bool ring,
                   const ParticleParams& p, const StateSink* sink) {
  RunWatch watch{p, {}};
  Recorder recorder(p, n, L, ring, mean_mass, sink);
  // Built from the bodies at the first stop, then advanced from its own clusters.
  std::optional<StickyHull> hull;
  auto reach = [&](double t) -> const StickyHull& {
    if (!hull)
      hull.emplace(build(t));
    else if (hull->time() != t)
      hull->advance(t);
    return *hull;
  };
  RunStop stop{StopReason::completed, p.t_end, 0.0};
  for (double t = recorder.next_stop(); t != Recorder::done; t = recorder.next_stop()) {
    if (!watch.interruption()) {
      stop = {StopReason::interrupted, hull ? hull->time() : 0.0, 0.0};
      break;
    }
    const StickyHull& h = reach(t);
    recorder.observe(t, chain_view(h), hull_counters(energy(), h));
  }
  const StickyHull& final_state = reach(stop.time);
  RunResult out = recorder.finish(chain_view(final_state), stop, hull_counters(energy(), final_state));
  out.wall_seconds = watch.elapsed();
  return out;
}

}  // namespace

RunResult simulate_hull(const Bodies& initial, double L, bool ring, const ParticleParams& p,
                        const StateSink* sink) {
  const double energy = kinetic_energy(initial);
  auto build = [&](double t) {
    return ring ? StickyHull::ring(initial, L, t) : StickyHull::line(initial, t);
  };
  const double mean_mass = total_mass(initial) / static_cast<double>(initial.size());
  RunResult out = run_hull(
      initial.size(), mean_mass, build, [energy] { return energy; }, L, ring, p, sink);
  TemperatureSums sums;
  sums.add(initial.v.data(), initial.m.data(), initial.size());
  out.initial_temperature = sums.temperature();
  return out;
}

// The kinetic energy and the temperature are summed as the bodies pass
// (TemperatureSums: the energy in their order, as kinetic_energy).
RunResult simulate_hull(InitialStream& initial, double L, bool ring, const ParticleParams& p,
                        const StateSink* sink) {
  TemperatureSums sums;
  const StickyHull::Chunks read = [&](std::size_t count, double* x, double* v, double* m) {
    initial.next(count, x, v, m);
    sums.add(v, m, count);
  };
  const std::size_t n = initial.size();
  const double mean_mass = initial.mean_mass();
  auto build = [&](double t) {
    return ring ? StickyHull::ring(n, read, L, t) : StickyHull::line(n, read, t);
  };
  RunResult out = run_hull(
      n, mean_mass, build, [&sums] { return sums.kinetic_energy(); }, L, ring, p, sink);
  if (out.stop.reason != StopReason::interrupted) out.initial_temperature = sums.temperature();
  return out;
}

}  // namespace shockgas::particles::detail
