#include "shockgas/compare/snapshot_comparison.hpp"

#include "shockgas/compare/theory.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::compare {

namespace {

std::vector<double> eligible_shock_positions(const std::vector<continuum::Shock>& shocks, double min_mass) {
  std::vector<double> x;
  for (const auto& s : shocks)
    if (s.mass >= min_mass) x.push_back(s.x);
  return x;
}

// [first body, last body] of each eligible cluster (the last unrolled by +L if
// the cluster wraps), in order of position.
std::vector<Extent> eligible_cluster_extents(const Bodies& state, double L,
                                             const std::vector<particles::Cluster>& clusters,
                                             double min_mass) {
  const std::size_t n = state.size();
  std::vector<Extent> extents;
  for (const auto& c : clusters) {
    if (c.m < min_mass || c.count == 0) continue;
    const std::size_t last = c.first + c.count - 1;
    extents.push_back(Extent{state.x[c.first], state.x[last % n] + (last >= n ? L : 0.0)});
  }
  return extents;
}

// 1 where a cell holds mass, 0 where it is empty: an empty cell's velocity in a
// particle deposit is an interpolation, not data. (A continuum field's velocity
// is data everywhere, vacuum included: the exact solver's vacuum carries the
// ramp (x - q)/t, so continuum fits use every cell.)
std::vector<double> occupied(const std::vector<double>& mass_or_density) {
  std::vector<double> w(mass_or_density.size());
  for (std::size_t i = 0; i < w.size(); ++i) w[i] = mass_or_density[i] > 0 ? 1.0 : 0.0;
  return w;
}

}  // namespace

SnapshotParams snapshot_params(const CompareParams& c, double r, double delta, double mean_spacing,
                               double t) {
  SnapshotParams p;
  p.clusters = particles::gas_cluster_criteria(r, delta, mean_spacing, t);
  if (c.cluster_gap > 0) p.clusters.max_gap = c.cluster_gap;
  if (c.cluster_dv > 0) p.clusters.max_dv = c.cluster_dv;
  p.match_distance = c.match_distance;
  p.min_cluster_particles =
      c.min_cluster_particles > 0 ? c.min_cluster_particles : automatic_min_cluster_particles(t);
  p.deposit = c.deposit;
  return p;
}

SnapshotComparison compare_snapshot(const Bodies& state, std::size_t N,
                                    const continuum::ContinuumResult& field, const SnapshotParams& params) {
  require(N > 0, "initial.N", N, ">= 1");
  require(!field.v.empty(), "compare.cells", field.v.size(), ">= 1");
  require(field.t > 0, "compare.t", field.t, "> 0");
  require(params.min_cluster_particles >= 0, "compare.min_cluster_particles", params.min_cluster_particles,
          ">= 0");
  SnapshotComparison c;
  c.t = field.t;
  const double L = field.length;
  c.min_mass = params.min_cluster_particles * total_mass(state) / static_cast<double>(N);
  c.clusters = particles::find_clusters(state, L, params.clusters);
  c.shocks = find_shocks(field, params.shocks);
  c.particle_fields = deposit_on_grid(state, L, field.v.size(), params.deposit);
  c.match = match_shocks_to_clusters(c.shocks, c.clusters, L, MatchParams{params.match_distance, c.min_mass});
  c.n_shocks = c.match.eligible_shocks;
  c.n_clusters = c.match.eligible_clusters;
  c.sawtooth = fit_sawtooth_slopes(field.v, L, field.t, eligible_shock_positions(c.shocks, c.min_mass),
                                   params.sawtooth);
  c.particle_sawtooth = fit_sawtooth_between(c.particle_fields.v, L, field.t,
                                             eligible_cluster_extents(state, L, c.clusters, c.min_mass),
                                             params.sawtooth, occupied(c.particle_fields.mass));
  c.shock_count_ratio = shock_count_ratio(c.n_shocks, static_cast<double>(N), field.t);
  return c;
}

}  // namespace shockgas::compare
