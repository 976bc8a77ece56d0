#include "shockgas/app/run.hpp"

#include <csignal>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>

#include <unistd.h>

#include "plots.hpp"
#include "run_state.hpp"
#include "shockgas/continuum/solve.hpp"
#include "shockgas/core/error.hpp"
#include "shockgas/version.hpp"

namespace shockgas::app {

namespace fs = std::filesystem;

namespace {

// Temporary files removed if the run is interrupted (SIGINT, SIGTERM).
char g_partial_h5[4096] = "";
char g_partial_json[4096] = "";

extern "C" void remove_partials_and_exit(int sig) {
  if (g_partial_h5[0]) unlink(g_partial_h5);
  if (g_partial_json[0]) unlink(g_partial_json);
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

class PartialFiles {
 public:
  PartialFiles(const fs::path& h5, const fs::path& json) : h5_(h5), json_(json) {
    std::snprintf(g_partial_h5, sizeof g_partial_h5, "%s", h5.c_str());
    std::snprintf(g_partial_json, sizeof g_partial_json, "%s", json.c_str());
    std::signal(SIGINT, remove_partials_and_exit);
    std::signal(SIGTERM, remove_partials_and_exit);
  }
  ~PartialFiles() {
    std::error_code ec;
    fs::remove(h5_, ec);  // no-op once renamed
    fs::remove(json_, ec);
    g_partial_h5[0] = g_partial_json[0] = '\0';
    std::signal(SIGINT, SIG_DFL);
    std::signal(SIGTERM, SIG_DFL);
  }

 private:
  fs::path h5_, json_;
};

std::string utc_now() {
  std::time_t now = std::time(nullptr);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
  return buf;
}

}  // namespace

void write_provenance(Hdf5File& h5, nlohmann::ordered_json& summary, const Scene& scene) {
  h5.set_attribute("/", "shockgas_version", kVersion);
  h5.set_attribute("/", "git_commit", kGitCommit);
  h5.set_attribute("/", "created_utc", utc_now());
  h5.set_attribute("/", "scene_name", scene.name);
  h5.set_attribute("/", "scene_path", scene.path);
  std::string overrides;
  for (const auto& o : scene.overrides) overrides += (overrides.empty() ? "" : " ") + std::string("--set ") + o;
  h5.set_attribute("/", "overrides", overrides);
  h5.set_attribute("/", "scene_text", scene.text);
  h5.set_attribute("/", "resolved_parameters", resolved_scene_text(scene));
  summary["scene"] = scene.name;
  summary["shockgas_version"] = kVersion;
  summary["git_commit"] = kGitCommit;
  summary["overrides"] = scene.overrides;
}

namespace {

void write_report(const fs::path& dir, const RunState& state) {
  std::ofstream out(dir / "report.md");
  out << "# shockgas report: " << state.scene.name << "\n\n";
  if (!state.scene.description.empty()) out << state.scene.description << "\n\n";
  for (const auto& line : state.report) out << line << "\n";
}

}  // namespace

std::string brief(double value) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", value);
  return buf;
}

// Every solver checks its own limits (CFL bound, cells against nu, ...) when it
// starts; a zero-length solve runs those checks now, so that bad input stops
// the run before any work and before anything is written.
void preflight(const Scene& scene) {
  if (!scene.has_continuum) return;
  const InitialField field = make_initial_field(scene.initial, 0);
  try {
    for (const auto& name : scene.continuum.solvers) continuum::solve(name, field, scene.continuum, 0.0);
  } catch (const InputError& e) {
    const auto it = scene.key_origin.find(e.key());
    throw e.located(it != scene.key_origin.end() ? it->second : scene.path);
  }
}

std::string run_single(const Scene& scene, const fs::path& dir, const RunOptions& options) {
  preflight(scene);
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw InputError("--out", to_text(dir.string()), "a directory that can be created and written");
  const std::string tag = ".partial-" + std::to_string(getpid());
  const fs::path h5_path = dir / "result.h5", json_path = dir / "summary.json";
  PartialFiles partial(h5_path.string() + tag, json_path.string() + tag);

  nlohmann::ordered_json summary;
  ProgressBar progress(options.progress);
  {
    Hdf5File h5 = Hdf5File::create(h5_path.string() + tag);
    RunState state{scene, h5, summary, progress};
    write_provenance(h5, summary, scene);
    run_initial_stage(state);
    if (scene.has_particles) {
      run_particles_stage(state);
      run_analysis_stage(state);
    }
    if (scene.has_continuum) run_continuum_stage(state);
    if (scene.has_compare && scene.has_continuum) run_compare_stage(state);
    progress.finish();
    h5.close();
    write_report(dir, state);
  }
  {
    std::ofstream out(json_path.string() + tag);
    out << summary.dump(2) << "\n";
    if (!out) throw RunError("cannot write " + json_path.string());
  }
  fs::rename(h5_path.string() + tag, h5_path);
  fs::rename(json_path.string() + tag, json_path);
  if (options.plots && scene.output.plots) make_plots(dir.string());
  return dir.string();
}

std::string run_scene(const Scene& scene, const RunOptions& options) {
  const fs::path dir = options.out_dir.empty() ? fs::path("out") / scene.name : fs::path(options.out_dir);
  if (scene.has_sweep) return run_sweep(scene, dir, options);
  return run_single(scene, dir, options);
}

}  // namespace shockgas::app
