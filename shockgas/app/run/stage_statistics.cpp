// Stage [statistics]: the shock statistics of one run's own realizations, from
// their final clusters as the ensemble holds them (nothing read back from the
// files just written), the numbers `shockgas stats` gives for the same run.
#include <string>
#include <vector>

#include "shockgas/app/output/run_results.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::app {

StatisticsResult run_statistics_stage(const Scene& scene, const particles::EnsembleResult& ensemble) {
  StatisticsAbout about{scene.name, resolved_scene_text(scene), {scene.path}, 0, scene.particles.r};
  std::vector<Bodies> clusters;
  for (std::size_t k = 0; k < ensemble.final_clusters.size(); ++k) {
    const auto& found = ensemble.final_clusters[k];
    if (found && ensemble.stops.at(k).time == scene.particles.t_end)
      clusters.push_back(*found);
    else
      ++about.left_out;
  }
  if (clusters.empty())
    throw RunError("statistics: none of the " + std::to_string(ensemble.final_clusters.size()) +
                   " realizations reached particles.t_end = " + to_text(scene.particles.t_end));
  return {compare::shock_statistics(clusters, statistics_shape(scene)), std::move(about)};
}

}  // namespace shockgas::app
