#include "shockgas/particles/cluster_finder.hpp"

#include <algorithm>
#include <cmath>

#include "shockgas/core/bodies.hpp"
#include "shockgas/core/error.hpp"
#include "shockgas/particles/cluster_sums.hpp"

namespace shockgas::particles {

namespace {

void validate_input(const Bodies& b, double L, const ClusterCriteria& c) {
  detail::require_cluster_inputs(L, c);
  require(b.v.size() == b.size() && b.m.size() == b.size(), "cluster.bodies", b.size(),
          "x, v and m of equal length");
  require_finite_bodies(b, "cluster.bodies");  // a NaN x would fail the order below under another's name
  for (std::size_t i = 0; i + 1 < b.size(); ++i)
    require(b.x[i] <= b.x[i + 1], "cluster.bodies.x", b.x[i + 1], "positions sorted ascending");
  if (L > 0 && b.size() > 0)
    require(b.x.front() >= 0 && b.x.back() < L, "cluster.bodies.x", b.x.back(), "positions in [0, L)");
}

// Whether bodies i and j = i + 1 (ring: j = 0 after N - 1) belong to one cluster.
bool joined(const Bodies& b, std::size_t i, std::size_t j, double L, const ClusterCriteria& c) {
  const double gap = j > i ? b.x[j] - b.x[i] : b.x[j] + L - b.x[i];
  return c.joins(gap, b.v[j] - b.v[i]);
}

// The cluster of `count` bodies starting at `first` (indices taken mod N).
Cluster make_cluster(const Bodies& b, double L, std::size_t first, std::size_t count) {
  const std::size_t n = b.size();
  detail::ClusterSums sums;
  sums.start(first, b.x[first], b.v[first]);
  for (std::size_t s = 0; s < count; ++s) {
    const std::size_t i = (first + s) % n;
    sums.add(b.x[i] + (first + s >= n ? L : 0.0), b.v[i], b.m[i]);
  }
  return sums.done(L);
}

}  // namespace

std::vector<Cluster> find_clusters(const Bodies& b, double L, const ClusterCriteria& c) {
  validate_input(b, L, c);
  const std::size_t n = b.size();
  std::vector<Cluster> clusters;
  if (n == 0) return clusters;
  // Whether body i is joined to its right neighbour (ring: the last one to body 0).
  auto linked = [&](std::size_t i) {
    if (i + 1 < n) return joined(b, i, i + 1, L, c);
    return L > 0 && n > 1 && joined(b, n - 1, 0, L, c);
  };
  // Start at a body whose left neighbour is not joined to it; on a fully linked
  // ring every body is in one cluster, started at body 0.
  std::size_t start = 0;
  if (L > 0)
    for (std::size_t i = 0; i < n; ++i)
      if (!linked((i + n - 1) % n)) {
        start = i;
        break;
      }
  std::size_t walked = 0;
  while (walked < n) {
    const std::size_t first = (start + walked) % n;
    std::size_t count = 1;
    while (walked + count < n && linked((first + count - 1) % n)) ++count;
    clusters.push_back(make_cluster(b, L, first, count));
    walked += count;
  }
  return clusters;
}

ClusterCriteria default_cluster_criteria(double delta, double mean_spacing, double t) {
  require(std::isfinite(delta) && delta >= 0, "particles.delta", delta, "finite, >= 0");
  require(std::isfinite(mean_spacing) && mean_spacing > 0, "cluster.mean_spacing", mean_spacing,
          "finite, > 0");
  require(std::isfinite(t) && t >= 0, "cluster.t", t, "finite, >= 0");
  return ClusterCriteria{std::max(0.5 * mean_spacing, std::sqrt(delta * t * mean_spacing)), 5.0 * delta};
}

ClusterCriteria default_cluster_criteria(double delta, double mean_spacing) {
  return default_cluster_criteria(delta, mean_spacing, 0.0);
}

ClusterCriteria merged_bodies_criteria() { return ClusterCriteria{0.0, 0.0}; }

ClusterCriteria gas_cluster_criteria(double r, double delta, double mean_spacing, double t) {
  return r == 0.0 ? merged_bodies_criteria() : default_cluster_criteria(delta, mean_spacing, t);
}

MultiParticleRule::MultiParticleRule(double mean_particle_mass, std::size_t k)
    : heavy_mass_((static_cast<double>(k) - 0.5) * mean_particle_mass), body_count_counts_(k == 2) {
  require(std::isfinite(mean_particle_mass) && mean_particle_mass > 0, "cluster.mean_particle_mass",
          mean_particle_mass, "finite, > 0");
  require(k >= 2, "particles.min_cluster_particles", k, ">= 2");
}

}  // namespace shockgas::particles
