#include "shockgas/app/jobs/merge.hpp"

#include <algorithm>
#include <sstream>

#include "shockgas/app/directory/run_directory.hpp"
#include "shockgas/app/directory/run_target.hpp"
#include "shockgas/app/input/scene_parser.hpp"
#include "shockgas/app/jobs/parallel_run.hpp"
#include "shockgas/app/jobs/shard_file.hpp"
#include "shockgas/app/run/resources.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::app {

namespace fs = std::filesystem;

namespace {

void require_one_run(const std::vector<ShardHeader>& shards) {
  const ShardHeader& a = shards.front();
  auto build = [](const ShardHeader& h) {
    return "shockgas " + h.provenance.at("shockgas_version") + " (commit " + h.provenance.at("git_commit") +
           ")";
  };
  for (const ShardHeader& b : shards) {
    if (build(b) != build(a))
      throw InputError(
          "shards", to_text(b.dir),
          "shards written by one build: " + a.dir + " by " + build(a) + ", " + b.dir + " by " + build(b));
    const std::string pa = physics_of(a.provenance.at("resolved_parameters")),
                      pb = physics_of(b.provenance.at("resolved_parameters"));
    if (pa != pb)
      throw InputError(
          "shards", to_text(b.dir),
          "shards of one scene: " + b.dir + " differs from " + a.dir + " in " + first_difference(pb, pa));
  }
}

// The slices of each ensemble must tile [0, R): overlaps and gaps are named.
void require_tiling(const std::vector<ShardHeader>& shards, const std::vector<Scene>& ensembles,
                    const Scene& scene) {
  std::string missing, overlap;
  for (std::size_t e = 0; e < ensembles.size(); ++e) {
    if (!ensembles[e].has_particles) continue;
    const std::uint64_t R = ensembles[e].particles.realizations;
    struct Piece {
      Slice slice;
      std::string dir;
    };
    std::vector<Piece> pieces;
    for (const ShardHeader& h : shards) {
      const std::string v = h.shard.at("variants"), k = h.shard.at("realizations");
      const Slice variants = v == "all" ? Slice{0, ensembles.size()} : parse_slice(v, "variants");
      if (e >= variants.begin && e < variants.end)
        pieces.push_back({k == "all" ? Slice{0, R} : parse_slice(k, "realizations"), h.dir});
    }
    std::sort(pieces.begin(), pieces.end(),
              [](const Piece& a, const Piece& b) { return a.slice.begin < b.slice.begin; });
    const std::string where = scene.has_sweep ? " of " + ensembles[e].name : "";
    std::uint64_t covered = 0;
    const Piece* last = nullptr;
    for (const Piece& p : pieces) {
      if (p.slice.begin > covered) missing += " " + slice_text({covered, p.slice.begin}) + where;
      if (last && p.slice.begin < covered)
        overlap += (overlap.empty() ? " " : "; ") + last->dir + " and " + p.dir + " both hold " +
                   slice_text({p.slice.begin, std::min(covered, p.slice.end)}) + where;
      if (p.slice.end > covered) covered = p.slice.end, last = &p;
    }
    if (covered < R) missing += " " + slice_text({covered, R}) + where;
  }
  std::string given;
  for (const ShardHeader& h : shards) given += (given.empty() ? "" : " ") + h.dir;
  if (!overlap.empty())
    throw InputError("shards", given, "shards that hold each realization once; but" + overlap);
  if (!missing.empty())
    throw InputError(
        "shards", given,
        "shards that together hold every realization of the run; missing realizations" + missing);
}

}  // namespace

std::string merge_shards(const std::vector<std::string>& shard_dirs, const RunOptions& options) {
  std::vector<ShardHeader> shards;
  for (const auto& dir : shard_dirs) shards.push_back(read_shard_header(dir));
  if (shards.empty()) throw InputError("shards", "none", "one or more shard directories");
  require_one_run(shards);
  const ShardHeader& first = shards.front();
  const Scene scene =
      parse_scene(first.provenance.at("scene_text"), first.provenance.at("scene_path"), first.overrides);
  const EnsemblePlan plan(scene, std::nullopt, std::nullopt);
  std::vector<Scene> ensembles;
  for (std::size_t e = 0; e < plan.ensembles(); ++e) ensembles.push_back(plan.scene(e));
  require_tiling(shards, ensembles, scene);

  const fs::path dir = options.out_dir.empty() ? fs::path("out") / scene.name : fs::path(options.out_dir);
  check_target_spares(resolve_target(dir), dir.string(), shard_dirs, "shard being merged");
  check_resources(scene, dir, options.plots);        // as a run of the scene would
  RunDirectory out(dir, scene.name, options.force);  // locked and staged before the records are read

  std::vector<RealizationRecord> records;
  ParallelRun parallel{1, 1, shards.size()};
  double shard_seconds = 0;
  for (const ShardHeader& h : shards) {
    for (auto& r : read_shard_records(h.dir, h.verified)) records.push_back(std::move(r));
    parallel.ranks = std::max(parallel.ranks, static_cast<int>(std::min<std::uint64_t>(h.ranks, 1u << 30)));
    parallel.threads = std::max<std::size_t>(parallel.threads, h.threads);
    shard_seconds += h.wall_seconds;
  }
  return write_from_records(scene, plan, std::move(records), parallel, shard_seconds, out, dir, options,
                            scene.has_sweep ? nullptr : &plan.initial(0));
}

}  // namespace shockgas::app
