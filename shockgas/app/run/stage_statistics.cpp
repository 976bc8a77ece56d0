// Stage [statistics]: the shock statistics of one run's own realizations, from
// their final clusters as the ensemble holds them (nothing read back from the
// files just written), the numbers `shockgas stats` gives for the same run.
#include <string>
#include <utility>
#include <vector>

#include "shockgas/app/output/run_results.hpp"

namespace shockgas::app {

std::optional<StatisticsResult> run_statistics_stage(const Scene& scene,
                                                     particles::EnsembleResult& ensemble) {
  StatisticsAbout about{scene.name, resolved_scene_text(scene), {scene.path}, 0, scene.particles.r};
  std::vector<Bodies> clusters;
  for (std::size_t k = 0; k < ensemble.final_clusters.size(); ++k) {
    auto& found = ensemble.final_clusters[k];
    if (found && ensemble.stops.at(k).time == scene.particles.t_end) {
      clusters.push_back(std::move(*found));  // written already (Part::particles): not held twice
      found.reset();
    } else {
      ++about.left_out;
    }
  }
  if (clusters.empty()) return std::nullopt;
  return StatisticsResult{compare::shock_statistics(clusters, statistics_shape(scene)), std::move(about)};
}

}  // namespace shockgas::app
