#include "shockgas/app/jobs/shard_file.hpp"

#include <sstream>

#include "shockgas/app/files/durable_file.hpp"
#include "shockgas/app/files/manifest.hpp"
#include "shockgas/app/output/output_layout.hpp"
#include "shockgas/app/output/partial_outputs.hpp"
#include "shockgas/app/records/checkpoint.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::app {

namespace fs = std::filesystem;

namespace {

std::string slice_or_all(const std::optional<Slice>& s) { return s ? slice_text(*s) : "all"; }

std::map<std::string, std::string> attribute_map(const Hdf5File& h5, const std::string& object) {
  std::map<std::string, std::string> m;
  for (auto& [name, value] : h5.attributes(object)) m[name] = value;
  return m;
}

fs::path shard_file(const std::string& dir) { return fs::path(dir) / "result.h5"; }

void write_report(const fs::path& dir, const Scene& scene, const EnsemblePlan& plan) {
  std::ostringstream out;
  out << "# shockgas shard: " << scene.name << "\n\n"
      << "Realizations " << slice_or_all(plan.realization_slice()) << " of each ensemble"
      << (scene.has_sweep ? ", variants " + slice_or_all(plan.variant_slice()) : std::string()) << ": "
      << plan.items().size() << " realization(s). Merge the shards of the whole run with\n\n"
      << "    shockgas merge SHARD... --out DIR\n";
  write_file(dir / "report.md", out.str());
}

}  // namespace

void write_shard(const fs::path& dir, const Scene& scene, const EnsemblePlan& plan,
                 ComputedRecords computed) {
  PartialOutputs outputs(dir);
  // A shard is written in place: an earlier shard's manifest goes first, so
  // that no file is ever vouched for by a manifest of other files; the new one
  // is written last, over exactly the shard's files.
  std::error_code ec;
  fs::remove(dir / kManifestFile, ec);
  nlohmann::ordered_json summary;
  RunResults r;
  r.scene = &scene;
  r.shard = ShardResults{slice_or_all(plan.realization_slice()),
                         slice_or_all(plan.variant_slice()),
                         scene.overrides,
                         std::move(computed.records),
                         {computed.ranks, computed.threads, 0},
                         computed.wall_seconds};
  {
    Hdf5File h5 = Hdf5File::create(outputs.h5_path());
    for (Part part : {Part::provenance, Part::shard}) {
      write_part(h5, r, part);
      summarize_part(summary, r, part);
    }
    h5.close();
  }
  write_report(dir, scene, plan);
  outputs.commit(summary);
  write_manifest_of(dir, scene.name, {"report.md", "result.h5", "summary.json"});
}

ShardHeader read_shard_header(const std::string& dir) {
  const std::string allowed =
      "a shard directory, written by `shockgas run SCENE --realizations A:B --out DIR`";
  std::error_code ec;
  if (fs::is_regular_file(dir, ec))
    throw InputError("shard", to_text(dir), allowed + " (this is a file: give the directory that holds it)");
  if (!fs::is_regular_file(shard_file(dir))) {
    const bool interrupted = fs::exists(checkpoint_path(dir), ec);
    throw InputError(
        "shard", to_text(dir),
        allowed + (interrupted ? " (this one holds an interrupted shard's checkpoint" + resume_hint(dir) + ")"
                               : " (no result.h5 in it)"));
  }
  ShardHeader h;
  h.dir = dir;
  const Hdf5File h5 = Hdf5File::open(shard_file(dir).string());
  h.provenance = attribute_map(h5, "/");
  bool is_shard = false;
  for (const auto& d : h5.datasets()) is_shard = is_shard || d.path.rfind("/shard/", 0) == 0;
  if (!is_shard) throw InputError("shard", to_text(dir), allowed + " (this one holds a whole run)");
  h.shard = attribute_map(h5, "/shard");
  h.overrides = nlohmann::json::parse(h.shard.at("overrides")).get<std::vector<std::string>>();
  h.verified = h5.verification();
  return h;
}

std::vector<RealizationRecord> read_shard_records(const ShardHeader& shard) {
  const Hdf5File h5 = Hdf5File::open(shard_file(shard.dir).string(), shard.verified);
  std::map<std::pair<std::size_t, std::uint64_t>, RecordFields> fields;
  for (const auto& d : h5.datasets()) {
    if (d.path.rfind("/shard/", 0) != 0) continue;
    // /shard/{e}/{k}/{field...}
    const auto e_end = d.path.find('/', 7), k_end = d.path.find('/', e_end + 1);
    const std::size_t e = std::stoull(d.path.substr(7, e_end - 7));
    const std::uint64_t k = std::stoull(d.path.substr(e_end + 1, k_end - e_end - 1));
    fields[{e, k}].emplace_back(d.path.substr(k_end + 1), h5.read(d.path));
  }
  std::vector<RealizationRecord> records;
  for (auto& [key, f] : fields) records.push_back({key.first, key.second, from_fields(f)});
  return records;
}

}  // namespace shockgas::app
