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
#include "shockgas/core/error.hpp"

namespace shockgas::app {

namespace fs = std::filesystem;

namespace {

std::string shape_text(const std::vector<std::uint64_t>& shape) {
  std::string s = "(";
  for (std::size_t i = 0; i < shape.size(); ++i) s += (i ? ", " : "") + std::to_string(shape[i]);
  return s + (shape.size() == 1 ? ",)" : ")");
}

std::string intact_text(Verification v) {
  switch (v) {
    case Verification::manifest:
      return "  (intact: size and SHA-256 as its manifest.json records)";
    case Verification::own_checksum:
      return "  (intact: size and SHA-256 as its first 512 bytes record)";
    case Verification::no_manifest:
    case Verification::damaged:
      break;
  }
  return "";
}

// The listing of a file's contents; every text from the file is shown as
// printable text (a damaged or hostile file may hold any byte).
std::string describe(const ResultContents& file) {
  std::ostringstream out;
  out << file.path << intact_text(file.verification) << "\n\nprovenance:\n";
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

// A directory holding a checkpoint and no result (checkpoint.hpp): a run that
// stopped; how far it got and how to continue it. InputError for a damaged
// checkpoint or another build's.
std::string describe_checkpoint(const fs::path& dir) {
  Checkpoint c;
  try {
    c = read_checkpoint(dir);
  } catch (const InputError& e) {  // read_checkpoint names --resume; here the directory was given as RESULT
    throw InputError("RESULT", e.value(), "a stopped run's directory: " + e.allowed());
  }
  const EnsemblePlan plan(checkpoint_scene(c, nullptr),
                          parse_optional_slice(c.realizations, "--realizations"),
                          parse_optional_slice(c.variants, "--variants"));
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

// Where the damage of a file that failed its checksum lies, read through the
// result reader (in a child process): the datasets whose chunks fail their
// Fletcher32 checksums, or the library's reason where it cannot read the
// file's structure.
std::string damaged_parts(const fs::path& file) {
  std::string shockgas_version, layout_version;
  try {
    const ResultContents read = read_every_chunk(file, Verification::damaged);
    shockgas_version = read.attribute("/", "shockgas_version");
    layout_version = read.attribute("/", "layout_version");
  } catch (const FileProblem& e) {
    const bool chunks = e.problem() == "damaged" && e.detail().rfind("dataset ", 0) == 0;
    return chunks ? e.detail() : "its HDF5 structure: " + e.detail();
  }
  if (shockgas_version.empty())
    return "it reads back, but without /@shockgas_version, which every result file carries: not written by "
           "shockgas";
  if (layout_version.empty())  // layout 1.0: no checksum inside the file tells where
    return "every dataset and attribute reads back, but a file of layout 1.0 carries no checksums of its own "
           "(its datasets unfiltered): where its bytes differ cannot be told, only that they do";
  return "every dataset and attribute reads back whole: the damage lies in its own checksum block, in bytes "
         "no read uses, or in metadata the library passes over";
}

// check_result_file(file), a damage named where it lies (damaged_parts).
Verification checked_naming_damage(const fs::path& file) {
  try {
    return check_result_file(file);
  } catch (const FileProblem& e) {
    if (e.problem() != "damaged") throw;
    throw result_problem(file.string(), "damaged", e.detail() + "; " + damaged_parts(file));
  }
}

}  // namespace

std::string describe_result(const std::string& path) {
  std::error_code ec;
  if (fs::is_directory(path, ec) && !fs::exists(fs::path(path) / "result.h5", ec)) {
    if (fs::exists(checkpoint_path(path), ec)) return describe_checkpoint(path);  // a run that stopped
    // An output directory without a result file by its own manifest (`shockgas
    // bench`): nothing to describe but its files.
    if (const auto manifest = read_manifest(path); manifest && !manifest->find("result.h5"))
      return path + ": the output of \"" + manifest->scene + "\", which has no result file\n";
  }
  const fs::path file = result_file_of(path);
  const Verification checked = checked_naming_damage(file);
  // Even a file whose bytes are as written has every chunk read, its Fletcher32
  // checked (a chunk damaged before its file's checksum was taken); the warning
  // once the reading has shown a file of layout 1.0 (a later one cannot lack its checksum).
  const ResultContents contents = read_every_chunk(file, checked);
  if (checked == Verification::no_manifest)
    std::cerr << "shockgas: warning: " << unverified_warning(file) << "\n";
  return describe(contents);
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
  if (!manifest && fs::is_directory(path, ec) && fs::exists(file, ec)) {
    // Every run directory of layout 1.0 on has one: it was removed, and the
    // directory's other files (summary.json, report.md, ...) vouch for nothing.
    std::cerr << "shockgas: warning: " << shown.string() << " has no " << kManifestFile
              << ": its files besides result.h5 cannot be checked\n";
    return {"\nfiles of " + shown.string() + ": no " + kManifestFile + ", none checked but result.h5\n", "",
            shown.string()};
  }
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
