// shockgas animate DIR (animate.hpp).
#include "shockgas/app/cli/animate.hpp"

#include <filesystem>
#include <iostream>
#include <optional>

#include "shockgas/app/directory/result_check.hpp"
#include "shockgas/app/directory/run_directory.hpp"
#include "shockgas/app/directory/run_target.hpp"
#include "shockgas/app/files/manifest.hpp"
#include "shockgas/app/output/result_reader.hpp"
#include "shockgas/app/report/plots.hpp"
#include "shockgas/app/report/report_html.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::app {

namespace fs = std::filesystem;

bool has_frames(const std::string& result_path) {
  const ResultContents file = read_result(result_path);
  // As `shockgas info` says: a file without a manifest entry is read as it is.
  if (!file.verified()) std::cerr << "shockgas: warning: " << unverified_warning(result_path) << "\n";
  for (const auto& d : file.datasets)
    if (d.path == "/animation/t") return true;
  return false;
}

namespace {

// The first variant directory of a sweep's output directory (its manifest
// lists the variants' manifests), or "" where it is not a sweep's.
std::string first_variant(const Manifest& manifest) {
  const std::string tail = std::string("/") + kManifestFile;
  for (const ManifestEntry& e : manifest.files)
    if (e.path.size() > tail.size() && e.path.compare(e.path.size() - tail.size(), tail.size(), tail) == 0)
      return e.path.substr(0, e.path.size() - tail.size());
  return "";
}

}  // namespace

namespace {

// The run's files, as the animation starts from them, into staging: result.h5
// (which the animation only reads) linked where the file system allows, the
// others copied (the animation writes report.html and its own files anew, and
// a log where a script fails); manifest.json and report.html are written anew.
void stage_run(const fs::path& dir, const fs::path& staging) {
  for (const auto& entry : fs::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (name == kManifestFile || name == "report.html") continue;
    std::error_code ec;
    if (name == "result.h5") fs::create_hard_link(entry.path(), staging / name, ec);
    if (name != "result.h5" || ec)
      fs::copy(entry.path(), staging / name, fs::copy_options::recursive | fs::copy_options::copy_symlinks);
  }
}

}  // namespace

void animate(const std::string& dir) {
  const std::string result = (fs::path(dir) / "result.h5").string();
  require(fs::is_regular_file(result), "DIR", dir, "a run's output directory, holding result.h5");
  const auto manifest = read_manifest(dir);
  if (const std::string variant = manifest ? first_variant(*manifest) : ""; !variant.empty())
    throw InputError(
        "DIR", to_text(dir),
        "a run's output directory; this one is a sweep's, whose frames are its variants': give one of them, "
        "e.g. " +
            (fs::path(dir) / variant).string());
  const std::optional<std::string> scene = scene_of_results(dir);
  require(scene.has_value(), "DIR", dir,
          "a run's output directory whose manifest.json or summary.json names its scene");
  // A sweep's variant: the sweep's lock, whose manifest lists the variant's files too.
  const fs::path target = resolve_target(dir), sweep_dir = target.parent_path();
  const std::string name = target.filename().string();
  const auto sweep = read_manifest(sweep_dir);
  const bool variant = sweep && sweep->find(name + "/" + kManifestFile);
  // The directory is replaced as a run's is (run_directory.hpp): locked, its
  // files staged with the animation, moved into place when all is written.
  RunDirectory run(dir, *scene, true,
                   variant ? RunDirectory::LockOn::enclosing : RunDirectory::LockOn::target);
  require(has_frames(result), "output.animation", std::string("false"),
          "true: the run must record its frames (run the scene again with --set output.animation=true)");
  stage_run(dir, run.staging());
  std::cerr << with_staging_as_target(make_animation(run.staging().string()));
  write_report_html(run.staging());
  const Manifest written = write_manifest(run.staging(), *scene);
  run.commit();
  // The variant's new manifest joins the sweep's.
  if (variant) update_manifest(sweep_dir, name, written);
}

}  // namespace shockgas::app
