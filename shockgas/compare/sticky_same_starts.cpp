#include "shockgas/compare/sticky_same_starts.hpp"

#include "shockgas/core/interrupt.hpp"
#include "shockgas/particles/simulate.hpp"

namespace shockgas::compare {

bool same_starts_apply(const particles::ParticleParams& gas, std::size_t N) {
  return gas.r > 0 && gas.realizations >= 2 &&
         static_cast<double>(N) * static_cast<double>(gas.realizations) <= kSameStartsBodies;
}

// The gas's sample times and geometry; nothing else recorded. An interrupt
// (a checkpoint request) ends a hull at a safe point: Interrupted, as the gas's
// own runs.
std::vector<std::vector<double>> sticky_T_rows(const InitialCondition& initial,
                                               const particles::ParticleParams& gas) {
  particles::ParticleParams sticky;
  sticky.r = 0.0;
  sticky.solver = particles::ParticleSolver::hull;
  sticky.geometry = gas.geometry;
  sticky.t_end = gas.t_end;
  sticky.samples = gas.samples;
  sticky.threads = 1;
  sticky.clusters = false;
  sticky.final_clusters = particles::ClusterRecord::never;
  std::vector<std::vector<double>> rows;
  rows.reserve(gas.realizations);
  for (std::size_t k = 0; k < gas.realizations; ++k) {
    particles::RunResult run = particles::simulate(initial, k, sticky);
    if (run.stop.reason == particles::StopReason::interrupted) throw Interrupted(interrupt_signal());
    rows.push_back(std::move(run.series.T));
  }
  return rows;
}

}  // namespace shockgas::compare
