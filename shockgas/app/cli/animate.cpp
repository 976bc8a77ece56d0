// shockgas animate DIR (animate.hpp).
#include "shockgas/app/cli/animate.hpp"

#include <filesystem>
#include <iostream>

#include "shockgas/app/directory/result_check.hpp"
#include "shockgas/app/directory/run_target.hpp"
#include "shockgas/app/files/manifest.hpp"
#include "shockgas/app/output/hdf5_file.hpp"
#include "shockgas/app/report/plots.hpp"
#include "shockgas/app/report/report_html.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::app {

bool has_frames(const std::string& result_path) {
  const Hdf5File file = Hdf5File::open(result_path);
  // As `shockgas info` says: a file without a manifest entry is read as it is.
  if (!file.verified()) std::cerr << "shockgas: warning: " << unverified_warning(result_path) << "\n";
  for (const auto& d : file.datasets())
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

void animate(const std::string& dir) {
  const std::string result = (std::filesystem::path(dir) / "result.h5").string();
  require(std::filesystem::is_regular_file(result), "DIR", dir,
          "a run's output directory, holding result.h5");
  const auto manifest = read_manifest(dir);  // read once: the manifests below are written anew
  if (const std::string variant = manifest ? first_variant(*manifest) : ""; !variant.empty())
    throw InputError(
        "DIR", to_text(dir),
        "a run's output directory; this one is a sweep's, whose frames are its variants': give one of them, "
        "e.g. " +
            (std::filesystem::path(dir) / variant).string());
  require(has_frames(result), "output.animation", std::string("false"),
          "true: the run must record its frames (run the scene again with --set output.animation=true)");
  std::cerr << make_animation(dir);
  write_report_html(dir);
  // The new files and the new report.html join the run's manifest, and a
  // sweep variant's files (its manifest among them) the sweep's.
  if (!manifest) return;
  const Manifest written = write_manifest(dir, manifest->scene);
  const std::filesystem::path variant = resolve_target(dir);
  const std::string name = variant.filename().string();
  if (const auto sweep = read_manifest(variant.parent_path());
      sweep && sweep->find(name + "/" + kManifestFile))
    update_manifest(variant.parent_path(), name, written);
}

}  // namespace shockgas::app
