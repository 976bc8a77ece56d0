// shockgas animate DIR (animate.hpp).
#include "shockgas/app/cli/animate.hpp"

#include <charconv>
#include <filesystem>
#include <iostream>
#include <optional>
#include <vector>

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

std::size_t recorded_frames(const std::string& result_path) {
  const std::string times = "/animation/t";
  const ResultContents file =
      read_result(result_path, [&](const std::string& path) { return path == times; });
  // As `shockgas info` says: a file without a manifest entry is read as it is.
  if (!file.verified()) std::cerr << "shockgas: warning: " << unverified_warning(result_path) << "\n";
  const auto it = file.values.find(times);
  return it == file.values.end() ? 0 : it->second.size();
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

// The whole of text as a decimal integer within [low, high]; nullopt otherwise.
std::optional<long> whole_number(const std::string& text, long low, long high) {
  long value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || value < low || value > high)
    return std::nullopt;
  return value;
}

// The script's --fps and --size for the request; InputError naming the option.
std::vector<std::string> picture_arguments(const AnimationRequest& request) {
  std::vector<std::string> args;
  if (!request.fps.empty()) {
    const auto fps = whole_number(request.fps, 1, 60);
    require(fps.has_value(), "--fps", request.fps, "an integer from 1 to 60 (frames per second)");
    args.insert(args.end(), {"--fps", std::to_string(*fps)});
  }
  if (!request.size.empty()) {
    const auto x = request.size.find('x');
    const long w = whole_number(request.size.substr(0, x), 160, 3840).value_or(1);
    const long h =
        x == std::string::npos ? 1 : whole_number(request.size.substr(x + 1), 90, 2160).value_or(1);
    require(w % 2 == 0 && h % 2 == 0, "--size", request.size,  // 1: not a number in range
            "WxH in pixels, each even (H.264 halves the colour planes), from 160x90 to 3840x2160, e.g. "
            "1920x1080");
    args.insert(args.end(), {"--size", std::to_string(w) + "x" + std::to_string(h)});
  }
  return args;
}

// The script's --frames for the request, against the frames the run recorded.
std::vector<std::string> frame_arguments(const AnimationRequest& request, std::size_t recorded) {
  if (request.frames.empty()) return {};
  const long most = static_cast<long>(recorded);
  const auto frames = whole_number(request.frames, 2, most);
  require(frames.has_value(), "--frames", request.frames,
          "an integer from 2 to " + std::to_string(most) +
              " (the frames result.h5 holds; a run records more with [output] animation_frames)");
  return {"--frames", std::to_string(*frames)};
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

void animate(const std::string& dir, const AnimationRequest& request) {
  std::vector<std::string> args = picture_arguments(request);  // before any file is read
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
  const std::size_t recorded = recorded_frames(result);
  require(recorded > 0, "output.animation", std::string("false"),
          "true: the run must record its frames (run the scene again with --set output.animation=true)");
  const std::vector<std::string> frames = frame_arguments(request, recorded);
  args.insert(args.end(), frames.begin(), frames.end());
  stage_run(dir, run.staging());
  std::cerr << with_staging_as_target(make_animation(run.staging().string(), "", args));
  write_report_html(run.staging());
  const Manifest written = write_manifest(run.staging(), *scene);
  run.commit();
  // The variant's new manifest joins the sweep's.
  if (variant) update_manifest(sweep_dir, name, written);
}

}  // namespace shockgas::app
