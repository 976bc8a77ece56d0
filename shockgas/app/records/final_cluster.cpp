#include "shockgas/app/records/final_cluster.hpp"

#include "shockgas/compare/heaviest.hpp"
#include "shockgas/compare/snapshot_comparison.hpp"

namespace shockgas::app {

std::optional<HeaviestCluster> heaviest_final_cluster(const Scene& scene, double length, double t,
                                                      const particles::StateReader& state) {
  const double spacing = length / static_cast<double>(scene.initial.N);
  const auto criteria =
      compare::snapshot_params(scene.compare, scene.particles.r, scene.particles.delta, spacing, t).clusters;
  const double L = scene.particles.geometry == particles::Geometry::ring ? length : 0.0;
  const std::optional<particles::Cluster> c = compare::heaviest_cluster(state, L, criteria);
  if (!c) return std::nullopt;
  return HeaviestCluster{c->x, c->v, c->m};
}

}  // namespace shockgas::app
