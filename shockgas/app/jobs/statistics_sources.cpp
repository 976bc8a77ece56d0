#include "shockgas/app/jobs/statistics_sources.hpp"

#include <algorithm>
#include <array>
#include <filesystem>
#include <sstream>

#include "shockgas/app/input/scene_parser.hpp"
#include "shockgas/app/jobs/shard_file.hpp"
#include "shockgas/app/output/result_reader.hpp"
#include "shockgas/core/error.hpp"
#include "shockgas/particles/params.hpp"

namespace shockgas::app {

namespace fs = std::filesystem;

namespace {

const char* const kAllowed =
    "a run, merged run or shard directory of a scene without [sweep] whose realizations recorded their "
    "final clusters (particles.final_clusters)";
const std::string kClusters = "/particles/realizations/clusters_";
const std::string kStopTime = "/particles/realizations/stop_time";

std::string no_clusters_hint(const Scene& scene) {
  if (!scene.has_particles)
    return std::string(kAllowed) + "; this one has none: its scene has no [particles] (no gas, no clusters)";
  return std::string(kAllowed) + "; this one has none: its scene set particles.final_clusters = \"" +
         name_of(scene.particles.final_clusters) + "\" for N = " + std::to_string(scene.initial.N) + " and " +
         std::to_string(scene.particles.realizations) + " realizations (auto records them when " +
         particles::final_clusters_auto_rule() + "; run it again with --set particles.final_clusters=always)";
}

const std::vector<double>& values_of(const ResultContents& h5, const std::string& path,
                                     const std::string& dir, const Scene& scene) {
  const auto it = h5.values.find(path);
  if (it == h5.values.end()) throw InputError("stats", to_text(dir), no_clusters_hint(scene));
  return it->second;
}

// A whole run's (or merged run's) realizations, split by clusters_count.
std::vector<StatisticsRealization> run_realizations(const ResultContents& h5, const std::string& dir,
                                                    const Scene& scene) {
  const auto& count = values_of(h5, kClusters + "count", dir, scene);
  const auto& x = values_of(h5, kClusters + "x", dir, scene);
  const auto& v = values_of(h5, kClusters + "v", dir, scene);
  const auto& m = values_of(h5, kClusters + "m", dir, scene);
  const auto& stop = values_of(h5, kStopTime, dir, scene);
  double total = 0;
  for (double c : count) total += c;
  if (stop.size() != count.size() || x.size() != v.size() || x.size() != m.size() ||
      total != static_cast<double>(x.size()))
    throw InputError("stats", to_text(dir),
                     std::string(kAllowed) + " (its clusters_count does not add up to its clusters)");
  std::vector<StatisticsRealization> out;
  std::size_t at = 0;
  for (std::size_t k = 0; k < count.size(); ++k) {
    StatisticsRealization r{k, stop[k], {}};
    const auto n = static_cast<std::size_t>(count[k]);
    r.clusters = {{x.begin() + at, x.begin() + at + n},
                  {v.begin() + at, v.begin() + at + n},
                  {m.begin() + at, m.begin() + at + n}};
    at += n;
    out.push_back(std::move(r));
  }
  return out;
}

// A shard's realizations from its records, its result.h5 checked once (by the
// reader that found it to be a shard).
std::vector<StatisticsRealization> shard_realizations(const std::string& dir, Verification checked,
                                                      const Scene& scene) {
  std::vector<StatisticsRealization> out;
  for (RealizationRecord& r : read_shard_records(dir, checked)) {
    if (!r.run.final_clusters) throw InputError("stats", to_text(dir), no_clusters_hint(scene));
    out.push_back({r.index, r.run.stop.time, std::move(*r.run.final_clusters)});
  }
  return out;
}

// The resolved parameters of the tables the statistics read ([scene], [initial],
// [particles], [sweep] as it stands): resolved text prints every table, also
// those the scene did not have, whose rules between tables (a continuum's or a
// comparison's) must not judge the gas.
std::string gas_tables(const std::string& resolved) {
  std::istringstream in(resolved);
  std::string out, table;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind('[', 0) == 0) table = line;
    if (table != "[continuum]" && table != "[compare]" && table != "[output]") out += line + "\n";
  }
  return out;
}

}  // namespace

std::string gas_of(const Scene& scene) {
  static const std::array<std::string, 6> particle_keys = {
      "r", "delta", "subthreshold", "restitution_law", "geometry", "t_end"};
  std::istringstream in(resolved_scene_text(scene));
  std::string table, out;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind('[', 0) == 0) {
      table = line;
      continue;
    }
    const std::string key = line.substr(0, line.find(' '));
    const bool keep = (table == "[initial]" && key != "seed") ||
                      (table == "[particles]" &&
                       std::find(particle_keys.begin(), particle_keys.end(), key) != particle_keys.end());
    if (keep && !key.empty()) out += table.substr(1, table.size() - 2) + "." + line + "\n";
  }
  return out;
}

StatisticsSource read_statistics_source(const std::string& dir) {
  std::error_code ec;
  if (fs::is_regular_file(dir, ec))
    throw InputError("stats", to_text(dir),
                     std::string(kAllowed) + " (this is a file: give the directory that holds it)");
  if (!fs::is_directory(dir, ec))
    throw InputError("stats", to_text(dir), std::string(kAllowed) + " (no such directory)");
  const ResultContents h5 = read_result(fs::path(dir), [](const std::string& path) {
    return path.rfind(kClusters, 0) == 0 || path == kStopTime;
  });
  const std::string resolved = h5.attribute("/", "resolved_parameters");
  if (resolved.empty())
    throw InputError("stats", to_text(dir), std::string(kAllowed) + " (its result.h5 names no scene)");
  StatisticsSource s{dir, parse_scene(gas_tables(resolved), dir + "/result.h5", {}), "", {}};
  if (s.scene.has_sweep)
    throw InputError("stats", to_text(dir),
                     std::string(kAllowed) + " (this is a sweep: give one variant's directory in it)");
  s.gas = gas_of(s.scene);
  const bool shard = std::any_of(h5.datasets.begin(), h5.datasets.end(),
                                 [](const DatasetInfo& d) { return d.path.rfind("/shard/", 0) == 0; });
  s.realizations =
      shard ? shard_realizations(dir, h5.verification, s.scene) : run_realizations(h5, dir, s.scene);
  return s;
}

}  // namespace shockgas::app
