#include "shockgas/app/jobs/shard_file.hpp"

#include <algorithm>
#include <charconv>
#include <cstdlib>
#include <sstream>

#include "shockgas/app/files/durable_file.hpp"
#include "shockgas/app/files/manifest.hpp"
#include "shockgas/app/output/layout_version.hpp"
#include "shockgas/app/output/output_layout.hpp"
#include "shockgas/app/output/result_reader.hpp"
#include "shockgas/app/records/checkpoint.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::app {

namespace fs = std::filesystem;

namespace {

std::string slice_or_all(const std::optional<Slice>& s) { return s ? slice_text(*s) : "all"; }

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
    Hdf5File h5 = Hdf5File::create((dir / "result.h5").string());
    for (Part part : {Part::provenance, Part::shard}) {
      write_part(h5, r, part);
      summarize_part(summary, r, part);
    }
    h5.close();
  }
  write_file(dir / "summary.json", summary.dump(2) + "\n");
  write_report(dir, scene, plan);
  write_manifest(dir, scene.name);
}

namespace {

// The attributes of a shard's group, each required: InputError naming the
// shard for one its result.h5 lacks (a file no shard run wrote).
std::map<std::string, std::string> required(const ResultContents& h5, const std::string& group,
                                            const std::vector<std::string>& names, const std::string& dir,
                                            const std::string& allowed) {
  std::map<std::string, std::string> m;
  for (const auto& [name, value] : h5.attributes_of(group)) m[name] = value;
  for (const std::string& name : names)
    if (!m.count(name))
      throw InputError("shard", to_text(dir),
                       allowed + " (its result.h5 has no " + (group == "/" ? "" : group) + "@" + name + ")");
  return m;
}

// A whole number of a shard's attribute or path; InputError naming the shard.
std::uint64_t whole_number(const std::string& text, const std::string& what, const std::string& dir) {
  std::uint64_t n = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), n);
  if (ec != std::errc() || end != text.data() + text.size() || text.empty())
    throw InputError(
        "shard", to_text(dir),
        "a shard whose result.h5 shockgas wrote (" + what + " is " + to_text(text) + ", not a whole number)");
  return n;
}

}  // namespace

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
  const ResultContents h5 = read_result(shard_file(dir));
  bool is_shard = false;
  for (const auto& d : h5.datasets) is_shard = is_shard || d.path.rfind("/shard/", 0) == 0;
  if (!is_shard) throw InputError("shard", to_text(dir), allowed + " (this one holds a whole run)");
  // A shard of another major holds other quantities under the same paths
  // (layout_version.hpp): merged with this build's, they would be averaged.
  const std::string stated = h5.attribute("/", "layout_version");
  const LayoutVersion layout =
      parse_layout_version(h5.path, stated.empty() ? std::nullopt : std::optional<std::string>(stated));
  if (layout.major != kLayoutVersion.major)
    throw InputError("shard", to_text(dir),
                     allowed + " of layout " + std::to_string(kLayoutVersion.major) +
                         ".x, as this shockgas writes (this one is of layout " + layout_version_text(layout) +
                         ": run its realizations again with this shockgas)");
  h.provenance =
      required(h5, "/", {"shockgas_version", "git_commit", "resolved_parameters", "scene_text", "scene_path"},
               dir, allowed);
  h.shard =
      required(h5, "/shard", {"overrides", "realizations", "variants", "ranks", "threads", "wall_seconds"},
               dir, allowed);
  const auto overrides = nlohmann::json::parse(h.shard.at("overrides"), nullptr, false);
  if (!overrides.is_array() ||
      !std::all_of(overrides.begin(), overrides.end(), [](const nlohmann::json& o) { return o.is_string(); }))
    throw InputError("shard", to_text(dir), allowed + " (its /shard@overrides is not a JSON list of texts)");
  h.overrides = overrides.get<std::vector<std::string>>();
  h.ranks = whole_number(h.shard.at("ranks"), "/shard@ranks", dir);
  h.threads = whole_number(h.shard.at("threads"), "/shard@threads", dir);
  char* end = nullptr;
  h.wall_seconds = std::strtod(h.shard.at("wall_seconds").c_str(), &end);
  h.verified = h5.verification;
  return h;
}

std::vector<RealizationRecord> read_shard_records(const std::string& dir, Verification checked) {
  const ResultContents h5 = read_result(
      shard_file(dir), checked, [](const std::string& path) { return path.rfind("/shard/", 0) == 0; });
  std::map<std::pair<std::size_t, std::uint64_t>, RecordFields> fields;
  for (const auto& [path, values] : h5.values) {
    // /shard/{e}/{k}/{field...}
    const auto e_end = path.find('/', 7);
    const auto k_end = e_end == std::string::npos ? e_end : path.find('/', e_end + 1);
    if (k_end == std::string::npos)
      throw InputError("shard", to_text(dir),
                       "a shard whose result.h5 shockgas wrote (it holds " + printable(path) +
                           ", not /shard/{e}/{k}/{field})");
    const std::size_t e = whole_number(path.substr(7, e_end - 7), path, dir);
    const std::uint64_t k = whole_number(path.substr(e_end + 1, k_end - e_end - 1), path, dir);
    fields[{e, k}].emplace_back(path.substr(k_end + 1), values);
  }
  std::vector<RealizationRecord> records;
  for (auto& [key, f] : fields) records.push_back({key.first, key.second, from_fields(f)});
  return records;
}

}  // namespace shockgas::app
