#include "shockgas/app/jobs/statistics_run.hpp"

#include <iostream>
#include <map>

#include "shockgas/app/directory/run_directory.hpp"
#include "shockgas/app/directory/run_target.hpp"
#include "shockgas/app/files/manifest.hpp"
#include "shockgas/app/jobs/statistics_sources.hpp"
#include "shockgas/app/output/statistics_files.hpp"
#include "shockgas/app/report/plots.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::app {

namespace fs = std::filesystem;

namespace {

std::string all_of(const std::vector<std::string>& dirs) {
  std::string given;
  for (const auto& d : dirs) given += (given.empty() ? "" : " ") + d;
  return given;
}

// One gas, each realization (seed, index) once.
void require_one_gas(const std::vector<StatisticsSource>& sources) {
  const StatisticsSource& a = sources.front();
  std::map<std::pair<std::uint64_t, std::uint64_t>, std::string> seen;
  for (const StatisticsSource& s : sources) {
    if (s.gas != a.gas)
      throw InputError("stats", to_text(s.dir),
                       "directories of one gas (the same scene but for initial.seed and the realizations): " +
                           s.dir + " differs from " + a.dir + " in " + first_difference(s.gas, a.gas));
    for (const StatisticsRealization& r : s.realizations) {
      const auto [it, fresh] = seen.emplace(std::pair{s.scene.initial.seed, r.index}, s.dir);
      if (!fresh)
        throw InputError("stats", to_text(s.dir),
                         "directories that hold each realization once; " + it->second + " and " + s.dir +
                             " both hold realization " + std::to_string(r.index) + " of seed " +
                             std::to_string(s.scene.initial.seed) +
                             " (give a merged run or its shards, not both)");
    }
  }
}

}  // namespace

std::string run_statistics(const StatisticsOptions& options) {
  if (options.dirs.empty())
    throw InputError("stats", "none", "one or more run, merged run or shard directories");
  std::vector<StatisticsSource> sources;
  for (const auto& dir : options.dirs) sources.push_back(read_statistics_source(dir));
  require_one_gas(sources);
  const Scene& scene = sources.front().scene;

  const fs::path dir =
      options.out_dir.empty() ? fs::path("out") / statistics_run_name(scene.name) : fs::path(options.out_dir);
  check_target_spares(resolve_target(dir), dir.string(), options.dirs, "directory being read");
  RunDirectory out(dir, statistics_run_name(scene.name), options.force);

  // Every realization that reached t_end, in the order of the sources and
  // their indices: shards and their merged run give the same list.
  std::map<std::pair<std::uint64_t, std::uint64_t>, const Bodies*> reached;
  StatisticsAbout about{scene.name, resolved_scene_text(scene), options.dirs, 0, scene.particles.r};
  for (const StatisticsSource& s : sources)
    for (const StatisticsRealization& r : s.realizations) {
      if (r.stop_time == s.scene.particles.t_end)
        reached[{s.scene.initial.seed, r.index}] = &r.clusters;
      else
        ++about.left_out;
    }
  if (reached.empty())
    throw InputError("stats", all_of(options.dirs), "realizations that reached t_end; none of these did");
  std::vector<Bodies> clusters;
  for (const auto& [key, b] : reached) clusters.push_back(*b);
  const std::string text =
      write_statistics(out.staging(), {compare::shock_statistics(clusters, statistics_shape(scene)), about});
  std::string notes;
  if (options.plots)
    notes = run_plot_script("plot_statistics.py", "SHOCKGAS_PLOT_STATISTICS_SCRIPT", out.staging().string(),
                            "statistics figure", "plots.log");
  write_manifest(out.staging(), statistics_run_name(scene.name));
  out.commit();
  if (!notes.empty()) std::cerr << notes;
  if (!options.quiet) std::cout << text << "Written to " << dir.string() << "/\n";
  return dir.string();
}

}  // namespace shockgas::app
