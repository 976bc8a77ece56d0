// Stage 3: shocks are clusters. The particle state and the continuum field at
// the same time are compared (shockgas/compare/snapshot_comparison.hpp), and the
// clusters' masses binned against the exact shock-mass law (shockgas/compare/shock_mass_law.hpp).
#include <algorithm>
#include <cmath>

#include "shockgas/app/output/run_results.hpp"
#include "shockgas/compare/shock_mass_law.hpp"
#include "shockgas/compare/shock_statistics.hpp"
#include "shockgas/continuum/solve.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::app {

namespace {

const continuum::ContinuumResult& compared_field(const Scene& scene,
                                                 const std::vector<ContinuumRun>& continuum) {
  for (const auto& run : continuum)
    if (run.result.solver == scene.compare.solver) return run.result;
  throw RunError("compare: solver " + scene.compare.solver + " did not run");
}

// Edges 1.5, 2.5, 4.5, ... particles up to past the heaviest cluster.
std::vector<double> mass_edges(const std::vector<particles::Cluster>& clusters) {
  double heaviest = 0;
  for (const auto& c : clusters) heaviest = std::max(heaviest, c.m);
  return compare::doubling_mass_edges(heaviest);
}

std::vector<double> counts_in(const std::vector<double>& edges,
                              const std::vector<particles::Cluster>& clusters) {
  std::vector<double> count(edges.size() - 1, 0.0);
  for (const auto& c : clusters) {
    const auto bin = std::upper_bound(edges.begin(), edges.end(), c.m) - edges.begin() - 1;
    if (bin >= 0 && bin < static_cast<std::ptrdiff_t>(count.size())) count[bin] += 1;
  }
  return count;
}

// The cluster masses against the exact shock-mass law of a white-noise start.
void bin_masses(Comparison& c, const std::optional<compare::WhiteNoiseReferences>& exact) {
  const auto& s = c.snapshot;
  c.mass_edges = mass_edges(s.clusters);
  c.mass_count = counts_in(c.mass_edges, s.clusters);
  if (!exact) return;
  c.mass_exact =
      compare::expected_shocks_in_mass_bins(c.mass_edges, exact->D, exact->length, exact->density, s.t);
  // Beyond 12 masses a (mu = 12) the law is below exp(-280): the eligible count is complete.
  const double unit = exact->density * std::cbrt(4 * exact->D * s.t * s.t);
  const std::vector<double> eligible{s.min_mass, s.min_mass + 12 * unit};
  c.n_shocks_exact =
      compare::expected_shocks_in_mass_bins(eligible, exact->D, exact->length, exact->density, s.t).front();
}

}  // namespace

// Both models at one time: if the particles stopped before t_end (a collapse, a
// limit), the compared solver is run again to the time they reached.
Comparison run_comparison(const Scene& scene, const InitialCondition& initial,
                          const ParticleResults& particles, const std::vector<ContinuumRun>& continuum) {
  const double t = particles.ensemble.first.stop.time;
  const continuum::ContinuumResult& field = compared_field(scene, continuum);
  Comparison c;
  c.solver = scene.compare.solver;
  std::optional<continuum::ContinuumResult> rerun;
  if (t < field.t) {
    c.note = "particles stopped early; continuum re-run to their final time";
    rerun = continuum::solve(field.solver, initial.field(), scene.continuum, t);
  }
  const auto& compared = rerun ? *rerun : field;
  const double spacing = initial.length() / static_cast<double>(scene.initial.N);
  c.snapshot = compare::compare_snapshot(
      particles.ensemble.first.final_state, scene.initial.N, compared,
      compare::snapshot_params(scene.compare, scene.particles.r, scene.particles.delta, spacing, compared.t));
  bin_masses(c, particles.exact);
  return c;
}

}  // namespace shockgas::app
