// The heaviest shock of a field and the heaviest cluster of a state (heaviest.hpp).
#include "shockgas/compare/heaviest.hpp"

#include <algorithm>

#include "shockgas/compare/shock_detection.hpp"

namespace shockgas::compare {

std::optional<continuum::Shock> heaviest_shock(const continuum::ContinuumResult& field) {
  const auto shocks = find_shocks(field);
  const auto it = std::max_element(shocks.begin(), shocks.end(),
                                   [](const auto& a, const auto& b) { return a.mass < b.mass; });
  if (it == shocks.end() || it->mass <= 0) return std::nullopt;
  return *it;
}

std::optional<particles::Cluster> heaviest_cluster(const Bodies& state, double L,
                                                   const particles::ClusterCriteria& criteria) {
  if (state.size() == 0) return std::nullopt;
  const auto clusters = particles::find_clusters(state, L, criteria);
  return *std::max_element(clusters.begin(), clusters.end(),
                           [](const auto& a, const auto& b) { return a.m < b.m; });
}

std::optional<particles::Cluster> heaviest_cluster(const particles::StateReader& state, double L,
                                                   const particles::ClusterCriteria& criteria) {
  return particles::heaviest_cluster(state, L, criteria);
}

}  // namespace shockgas::compare
