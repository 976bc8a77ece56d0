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
#include "shockgas/continuum/registry.hpp"
#include "shockgas/particles/simulate.hpp"
#include "shockgas/core/error.hpp"
#include "shockgas/version.hpp"

namespace shockgas::app {

namespace fs = std::filesystem;

namespace {

// Temporary files of every open PartialOutputs (a sweep nests one per variant
// inside its own), removed if the run is interrupted (SIGINT, SIGTERM).
constexpr int kMaxPartial = 8;
char g_partial[kMaxPartial][4096];
volatile std::sig_atomic_t g_partial_count = 0;

extern "C" void remove_partials_and_exit(int sig) {
  for (int i = 0; i < g_partial_count; ++i) unlink(g_partial[i]);
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

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

// Every solver's own limits (CFL bound, cells against nu, ...) are checked by its
// registered preflight, without solving, and the particle engine checks a
// requested schedule against the initial bodies, so that bad input stops the
// run before any work and before anything is written.
void preflight(const Scene& scene) {
  try {
    if (scene.has_particles && scene.particles.solver == particles::ParticleSolver::events &&
        scene.particles.schedule == particles::Schedule::windows)
      particles::check_schedule(make_initial_bodies(scene.initial, 0), scene.particles);
    if (!scene.has_continuum) return;
    const InitialField field = make_initial_field(scene.initial, 0);
    for (const auto& name : scene.continuum.solvers)
      continuum::preflight(name, field, scene.continuum, scene.continuum_t_end());
  } catch (const InputError& e) {
    const auto it = scene.key_origin.find(e.key());
    throw e.located(it != scene.key_origin.end() ? it->second : scene.path);
  }
}

PartialOutputs::PartialOutputs(const fs::path& dir) : dir_(dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw InputError("--out", to_text(dir.string()), "a directory that can be created and written");
  const std::string tag = ".partial-" + std::to_string(getpid());
  h5_tmp_ = (dir / "result.h5").string() + tag;
  json_tmp_ = (dir / "summary.json").string() + tag;
  if (g_partial_count + 2 > kMaxPartial) throw RunError("too many nested result directories");
  for (const auto& path : {h5_tmp_, json_tmp_}) {
    const int slot = g_partial_count;
    std::snprintf(g_partial[slot], sizeof g_partial[0], "%s", path.c_str());
    g_partial_count = slot + 1;  // published after the path is complete
  }
  std::signal(SIGINT, remove_partials_and_exit);
  std::signal(SIGTERM, remove_partials_and_exit);
}

PartialOutputs::~PartialOutputs() {
  std::error_code ec;
  fs::remove(h5_tmp_, ec);  // no-op once renamed
  fs::remove(json_tmp_, ec);
  g_partial_count = g_partial_count - 2;
  if (g_partial_count == 0) {
    std::signal(SIGINT, SIG_DFL);
    std::signal(SIGTERM, SIG_DFL);
  }
}

void PartialOutputs::commit(const nlohmann::ordered_json& summary) {
  {
    std::ofstream out(json_tmp_);
    out << summary.dump(2) << "\n";
    if (!out) throw RunError("cannot write " + json_tmp_);
  }
  fs::rename(h5_tmp_, dir_ / "result.h5");
  fs::rename(json_tmp_, dir_ / "summary.json");
}

std::string run_single(const Scene& scene, const fs::path& dir, const RunOptions& options) {
  PartialOutputs outputs(dir);
  nlohmann::ordered_json summary;
  ProgressBar progress(options.progress);
  {
    Hdf5File h5 = Hdf5File::create(outputs.h5_path());
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
  outputs.commit(summary);
  if (options.plots && scene.output.plots) make_plots(dir.string());
  return dir.string();
}

std::string run_scene(const Scene& scene, const RunOptions& options) {
  const fs::path dir = options.out_dir.empty() ? fs::path("out") / scene.name : fs::path(options.out_dir);
  if (scene.has_sweep) return run_sweep(scene, dir, options);
  preflight(scene);
  return run_single(scene, dir, options);
}

}  // namespace shockgas::app
