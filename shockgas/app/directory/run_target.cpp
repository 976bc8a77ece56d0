#include "shockgas/app/directory/run_target.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "shockgas/app/files/data_dir.hpp"
#include "shockgas/app/files/manifest.hpp"
#include "shockgas/app/records/checkpoint.hpp"
#include "shockgas/app/records/state_file.hpp"
#include "shockgas/core/error.hpp"
#include "shockgas/studies/tail_study.hpp"

namespace shockgas::app {

namespace fs = std::filesystem;

namespace {

[[noreturn]] void refuse(const std::string& out, const std::string& allowed) {
  throw InputError("--out", to_text(out), allowed);
}

// Whether a is b or a directory above b.
bool contains(const fs::path& a, const fs::path& b) {
  const auto [end_a, at_b] = std::mismatch(a.begin(), a.end(), b.begin(), b.end());
  return end_a == a.end() || (std::next(end_a) == a.end() && end_a->empty());
}

std::vector<std::pair<std::string, fs::path>> protected_directories() {
  std::vector<std::pair<std::string, fs::path>> dirs;
  std::error_code ec;
  dirs.emplace_back("the current directory", fs::current_path(ec));
  if (const char* home = std::getenv("HOME"); home && *home) dirs.emplace_back("the home directory", home);
  // The folder shockgas reads its plots from: in a build tree they link into the sources.
  if (const auto data = data_dir())
    dirs.emplace_back("shockgas's own files", fs::weakly_canonical(*data / "plots", ec).parent_path());
  for (auto& [what, dir] : dirs) dir = fs::weakly_canonical(dir, ec);
  return dirs;
}

// Files an older shockgas (without manifest.json) wrote into a run directory,
// or into the output directory of `shockgas tail`; and what killed runs of
// older versions left (*.partial-PID).
bool legacy_run_file(const fs::path& relative) {
  const std::string name = relative.filename().string(), extension = relative.extension().string();
  if (name.find(".partial-") != std::string::npos) return true;
  if (std::find(studies::kTailFiles.begin(), studies::kTailFiles.end(), name) != studies::kTailFiles.end())
    return true;
  return run_output_name(relative) && name != kManifestFile && extension != ".log" &&
         extension != ".csv";  // the tail's tables by name only: a directory of CSV files may be anyone's
}

// The first entry under dir that is not a result of a run: not listed in the
// manifest (or, without one, not a file an older version wrote). Entries that
// vanish while they are listed are skipped: in an MPI job every rank checks the
// directory while rank 0 may already write a checkpoint through a temporary
// file (checkpoint.bin.partial-PID) and rename it. Paths are taken lexically,
// with no call that resolves a name (fs::relative would), so a name gone
// between the listing and the check cannot fail the run.
std::optional<std::string> foreign_entry(const fs::path& dir, const std::optional<Manifest>& manifest) {
  // A subdirectory removed while it is entered ends the listing with ENOENT:
  // the listing starts again rather than pass what it did not see.
  for (int attempt = 0;; ++attempt) {
    std::error_code ec;
    fs::recursive_directory_iterator it(dir, ec), end;
    for (; !ec && it != end; it.increment(ec)) {
      const auto type = it->symlink_status(ec).type();
      if (ec || type == fs::file_type::not_found) {
        ec.clear();
        continue;
      }
      if (type == fs::file_type::directory) continue;
      const fs::path relative = it->path().lexically_relative(dir);
      const bool ours = type != fs::file_type::regular   ? false
                        : run_in_progress_file(relative) ? true  // an interrupted run's, to resume
                        : manifest ? relative == kManifestFile || manifest->find(relative.generic_string())
                                   : legacy_run_file(relative);
      if (!ours) return relative.generic_string();
    }
    if (!ec) return std::nullopt;
    if (ec != std::errc::no_such_file_or_directory || attempt == 2)
      throw fs::filesystem_error("cannot list the output directory", dir, ec);
  }
}

std::string read_text(const fs::path& file, std::uintmax_t limit) {
  std::error_code ec;
  if (!fs::is_regular_file(file, ec) || fs::file_size(file, ec) > limit) return "";
  std::ifstream in(file);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

bool run_output_name(const fs::path& relative) {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n = {"result.h5",     "result.xdmf",  "summary.json", "report.md",
                                  "report.html",   kManifestFile,  "plots.log",    "animation.log",
                                  "statistics.h5", "statistics.md"};
    n.insert(n.end(), studies::kTailFiles.begin(), studies::kTailFiles.end());  // also .csv, below
    return n;
  }();
  static const std::vector<std::string> extensions = {".png", ".gif", ".mp4", ".svg", ".csv"};
  const std::string name = relative.filename().string();
  return std::find(names.begin(), names.end(), name) != names.end() ||
         std::find(extensions.begin(), extensions.end(), relative.extension().string()) != extensions.end();
}

bool run_in_progress_file(const fs::path& relative) {
  return !relative.has_parent_path() && (is_checkpoint_file(relative) || is_state_file(relative));
}

fs::path resolve_target(const fs::path& out) {
  std::error_code ec;
  fs::path resolved = fs::weakly_canonical(fs::absolute(out, ec), ec);
  if (ec) resolved = fs::absolute(out).lexically_normal();
  // "out/bench/" names out/bench: without the trailing separator its name is
  // not empty, so the lock and the staging directory go beside it, not into it.
  while (!resolved.has_filename() && resolved != resolved.root_path()) resolved = resolved.parent_path();
  return resolved;
}

void check_target_path(const fs::path& target, const std::string& out) {
  const std::string replaced = " (a run replaces its output directory as a whole)";
  if (target == target.root_path()) refuse(out, "a directory other than the root directory" + replaced);
  for (const auto& [what, dir] : protected_directories())
    if (contains(target, dir))
      refuse(out, "a directory that is neither " + what + " (" + dir.string() + ") nor above it" + replaced);
  std::error_code ec;
  const auto status = fs::symlink_status(target, ec);
  if (status.type() == fs::file_type::not_found) return;
  if (status.type() != fs::file_type::directory) refuse(out, "a directory (this is not one)");
  struct stat here {
  }, above{};
  if (::stat(target.c_str(), &here) != 0 || ::stat(target.parent_path().c_str(), &above) != 0) return;
  if (here.st_dev != above.st_dev)
    refuse(out, "a directory that is not a mount point (give a directory inside it)" + replaced);
  // rename(2) in a directory with the sticky bit (/tmp, shared scratch space):
  // only the owner of the entry or of the directory, or a process with
  // CAP_FOWNER (taken here as root), may move the entry (EPERM). Refused now,
  // not after the run has computed its results and cannot put them in place.
  const uid_t me = ::geteuid();
  if ((above.st_mode & S_ISVTX) != 0 && me != 0 && here.st_uid != me && above.st_uid != me) {
    const std::string why = target.parent_path().string() +
                            " has the sticky bit: only the owner of an entry may move it, and this directory "
                            "belongs to user " +
                            std::to_string(here.st_uid) + ", not to " + std::to_string(me);
    refuse(out, "a directory this user may replace (" + why + ")");
  }
}

void check_target_spares(const fs::path& target, const std::string& out,
                         const std::vector<std::string>& inputs, const std::string& what) {
  for (const std::string& input : inputs) {
    const fs::path resolved = resolve_target(input);
    if (contains(target, resolved))
      refuse(out, "a directory that neither is nor holds a " + what + " (" + input + " is " +
                      (resolved == target ? "this directory" : "in it") +
                      "; the output directory is replaced as a whole)");
    if (contains(resolved, target))
      refuse(out,
             "a directory outside every " + what + " (it is in " + input +
                 ", whose files its manifest lists: a directory written into it would be a foreign file)");
  }
}

std::optional<std::string> scene_of_results(const fs::path& dir) {
  if (const auto manifest = read_manifest(dir)) return manifest->scene;
  const auto summary = nlohmann::json::parse(read_text(dir / "summary.json", 64u << 20), nullptr, false);
  if (summary.is_object() && summary.contains("scene") && summary["scene"].is_string())
    return summary["scene"].get<std::string>();
  std::error_code ec;
  if (fs::exists(dir / studies::kTailFiles.back(), ec)) return "tail";  // `shockgas tail` of an older version
  return std::nullopt;
}

namespace {

// The name of the scene whose interrupted run left its checkpoint in dir, or
// "" where none can be read.
std::string interrupted_scene(const fs::path& dir) {
  try {
    return checkpoint_scene_name(read_checkpoint(dir));
  } catch (const std::exception&) {
    return "";
  }
}

}  // namespace

void check_target_contents(const fs::path& target, const std::string& out, const std::string& scene,
                           bool force) {
  std::error_code ec;
  if (!fs::is_directory(target, ec) || fs::is_empty(target, ec)) return;
  const auto manifest = read_manifest(target);
  if (const auto foreign = foreign_entry(target, manifest))
    refuse(out, "a new or empty directory, or one that holds only shockgas results (this one holds " +
                    *foreign +
                    ", which a run did not write; a run replaces its output directory as a whole)");
  const auto theirs = scene_of_results(target);
  if (theirs == scene || force) return;
  const auto in_progress = [](const fs::directory_entry& e) {
    return run_in_progress_file(e.path().filename());
  };
  if (!theirs && std::all_of(fs::directory_iterator(target, ec), fs::directory_iterator(), in_progress)) {
    // Only the checkpoint and state files of an interrupted run (checkpoint.hpp,
    // state_file.hpp), or the state files this run writes before its directory
    // is made: the same scene may start afresh over them; another command or
    // scene would throw the interrupted run's work away.
    if (!fs::exists(checkpoint_path(target), ec) || interrupted_scene(target) == scene) return;
    refuse(out,
           "a new or empty directory, or one that holds this scene's results (this one holds an interrupted "
           "run's checkpoint" +
               resume_hint(target) + "): give --force to replace it, or another --out");
  }
  refuse(out, "a new or empty directory, or one that holds this scene's results (this one holds " +
                  (theirs ? "the results of scene \"" + *theirs + "\""
                          : std::string("results of an unknown scene")) +
                  "): give --force to replace them, or another --out");
}

}  // namespace shockgas::app
