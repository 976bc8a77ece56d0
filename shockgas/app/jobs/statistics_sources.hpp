#pragma once
// What `shockgas stats` reads of a directory: each realization's clusters of
// at least two particles at its end, from a run's (or merged run's) result.h5
// (/particles/realizations/clusters_*) or a shard's records (shard_file.hpp),
// with the scene they are of.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "shockgas/app/scene/scene.hpp"
#include "shockgas/compare/shock_statistics.hpp"
#include "shockgas/core/bodies.hpp"

namespace shockgas::app {

struct StatisticsRealization {
  std::uint64_t index = 0;  // realization k of the scene (seed realization_seed(seed, k))
  double stop_time = 0;     // when it ended [time]
  Bodies clusters;          // its clusters of >= 2 particles at stop_time, in order of x
};

struct StatisticsSource {
  std::string dir;  // as given
  Scene scene;      // the resolved scene of its result file
  std::string gas;  // what must agree between sources (gas_of)
  std::vector<StatisticsRealization> realizations;
};

// Reads dir (a run, a merged run or a shard). InputError naming it when it is
// none of these, is a sweep, or holds no final clusters (with the key that
// records them); FileProblem for a damaged file.
StatisticsSource read_statistics_source(const std::string& dir);

// The scene's keys that decide the statistics: the initial condition but its
// seed, the collision rule, the geometry and t_end, one "table.key = value"
// per line (sources with different seeds are independent samples of one gas).
std::string gas_of(const Scene& scene);

}  // namespace shockgas::app
