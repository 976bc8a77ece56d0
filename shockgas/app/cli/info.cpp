#include "shockgas/app/cli/info.hpp"

#include <iostream>
#include <optional>
#include <sstream>

#include "shockgas/app/directory/result_check.hpp"
#include "shockgas/app/ensemble/ensemble_plan.hpp"
#include "shockgas/app/input/resumed_scene.hpp"
#include "shockgas/app/output/output_layout.hpp"
#include "shockgas/app/output/result_reader.hpp"
#include "shockgas/app/records/checkpoint.hpp"
#include "shockgas/app/records/run_state_file.hpp"
#include "shockgas/app/report/report.hpp"

namespace shockgas::app {

namespace fs = std::filesystem;

namespace {

std::string shape_text(const std::vector<std::uint64_t>& shape) {
  std::string s = "(";
  for (std::size_t i = 0; i < shape.size(); ++i) s += (i ? ", " : "") + std::to_string(shape[i]);
  return s + (shape.size() == 1 ? ",)" : ")");
}

// The listing of a file's contents; every text from the file is shown as
// printable text (a damaged or hostile file may hold any byte).
std::string describe(const ResultContents& file) {
  std::ostringstream out;
  out << file.path << (file.verified() ? "  (intact: size and SHA-256 as its manifest.json records)" : "")
      << "\n\nprovenance:\n";
  std::string scene_text, resolved;
  for (const auto& [name, value] : file.attributes_of("/")) {
    if (name == "scene_text")
      scene_text = value;
    else if (name == "resolved_parameters")
      resolved = value;
    else
      out << "  " << printable(name) << ": " << printable(value) << "\n";
  }
  out << "\ndatasets (docs/output.md explains each):\n";
  for (const auto& d : file.datasets) {
    out << "  " << printable(d.path) << "  " << d.type << " " << shape_text(d.shape);
    if (!d.unit.empty()) out << "  [" << printable(d.unit) << "]";
    if (!d.description.empty()) out << "  " << printable(d.description);
    if (!find_in_layout(LayoutEntry::Kind::dataset, d.path)) out << "  (not in this version's layout)";
    out << "\n";
  }
  out << "\nscene (as given):\n" << printable(scene_text, true) << "\n";
  while (!resolved.empty() && resolved.back() == '\n') resolved.pop_back();
  if (!resolved.empty()) out << "resolved parameters:\n" << printable(resolved, true) << "\n";
  return out.str();
}

std::optional<Slice> slice_of(const std::string& text, const std::string& option) {
  return text.empty() ? std::nullopt : std::optional(parse_slice(text, option));
}

// A directory holding a checkpoint and no result (checkpoint.hpp): a run that
// stopped; how far it got and how to continue it. InputError for a damaged
// checkpoint or another build's.
std::string describe_checkpoint(const fs::path& dir) {
  const Checkpoint c = read_checkpoint(dir);
  const EnsemblePlan plan(checkpoint_scene(c, nullptr), slice_of(c.realizations, "--realizations"),
                          slice_of(c.variants, "--variants"));
  std::size_t saved = 0;
  std::error_code ec;
  for (const WorkItem& w : plan.items()) saved += fs::exists(run_state_path(dir, w.ensemble, w.index), ec);
  std::ostringstream out;
  out << dir.string() << ": a run stopped before its result was written; its checkpoint (scene \""
      << printable(checkpoint_scene_name(c)) << "\""
      << (c.realizations.empty() ? "" : ", realizations " + printable(c.realizations)) << ", shockgas "
      << printable(c.version) << " " << printable(c.commit) << ") holds " << c.records.size() << " of the "
      << plan.items().size() << " realizations finished, after " << brief(c.seconds) << " s of computing";
  if (saved) out << ", and the saved states of " << saved << " running";
  out << resume_hint(dir) << "\n";
  return out.str();
}

}  // namespace

std::string describe_result(const std::string& path) {
  // An output directory without a result file by its own manifest (`shockgas
  // bench`): nothing to describe but its files.
  std::error_code ec;
  if (fs::is_directory(path, ec) && !fs::exists(fs::path(path) / "result.h5", ec) &&
      fs::exists(checkpoint_path(path), ec))
    return describe_checkpoint(path);
  if (fs::is_directory(path, ec) && !fs::exists(fs::path(path) / "result.h5", ec))
    if (const auto manifest = read_manifest(path); manifest && !manifest->find("result.h5"))
      return path + ": the output of \"" + manifest->scene + "\", which has no result file\n";
  const fs::path file = result_file_of(path);
  const Verification checked = check_result_file(file);
  if (checked != Verification::manifest)
    std::cerr << "shockgas: warning: " << unverified_warning(file) << "\n";
  return describe(read_result(file, checked));
}

RunFilesCheck check_run_files(const std::string& path, bool result_checked) {
  std::error_code ec;
  const fs::path file = fs::is_directory(path, ec) ? fs::path(path) / "result.h5" : fs::path(path);
  const fs::path dir = file.parent_path().empty() ? "." : file.parent_path();
  // `info result.h5`, `info .` or `info ..` name the directory by its path, not as "." or ".."
  const std::string last = dir.filename().string();
  fs::path shown =
      last.empty() || last == "." || last == ".." ? fs::absolute(dir, ec).lexically_normal() : dir;
  if (!shown.has_filename() && shown != shown.root_path()) shown = shown.parent_path();
  const auto manifest = read_manifest(dir);
  if (!manifest) return {};
  // The result file itself was checked before it was described, if listed.
  const fs::path checked =
      result_checked && manifest->find(file.filename().string()) ? file.filename() : fs::path();
  const std::vector<FileState> states = check_listed_files(dir, *manifest, checked);
  std::size_t intact = 0, wrong = 0;
  std::ostringstream listing;
  for (const FileState& f : states) {
    intact += f.intact();
    if (f.intact()) continue;
    listing << "  " << f.path << ": " << f.problem << (f.detail.empty() ? "" : " (" + f.detail + ")") << "\n";
    wrong += f.problem != "not listed";
  }
  std::string differences = differences_of(states);
  const std::size_t listed = manifest->files.size();
  std::ostringstream head;
  head << "\nfiles of " << shown.string() << " (as " << kManifestFile << " lists them, scene \""
       << manifest->scene << "\"): ";
  if (wrong == 0)
    head << "all " << listed << " intact (size and SHA-256 as recorded)\n";
  else
    head << intact << " of " << listed << " intact\n";
  if (wrong)
    differences += " (" + std::to_string(wrong) + " of the " + std::to_string(listed) + " files " +
                   kManifestFile + " lists)";
  return {head.str() + listing.str(), differences, shown.string()};
}

void print_info(const std::string& path, std::ostream& out) {
  std::optional<FileProblem> undescribed;
  try {
    out << describe_result(path);
  } catch (const FileProblem& e) {
    undescribed = e;
  }
  const RunFilesCheck files = check_run_files(path, !undescribed);
  out << files.listing << std::flush;
  if (undescribed) throw *undescribed;
  if (!files.differences.empty())
    throw result_problem(files.directory, "not as its manifest.json records", files.differences);
}

std::string describe_layout() { return output_layout_markdown(); }

}  // namespace shockgas::app
