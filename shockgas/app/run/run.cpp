// Running a scene: the initial condition built once, every part the scene asks
// for in order (particles, continuum, comparison), each written as soon as it is
// done, then summary.json, the plots, report.md (with the time of each phase)
// and the manifest, all into the staging directory that replaces the output
// directory at the end.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>

#include "shockgas/app/directory/run_directory.hpp"
#include "shockgas/app/directory/run_target.hpp"
#include "shockgas/app/files/durable_file.hpp"
#include "shockgas/app/files/manifest.hpp"
#include "shockgas/app/output/output_layout.hpp"
#include "shockgas/app/output/theory_scopes.hpp"
#include "shockgas/app/output/xdmf_file.hpp"
#include "shockgas/app/report/plots.hpp"
#include "shockgas/app/report/report.hpp"
#include "shockgas/app/report/report_html.hpp"
#include "shockgas/app/run/progress_bar.hpp"
#include "shockgas/app/run/resources.hpp"
#include "shockgas/app/run/run_internal.hpp"
#include "shockgas/continuum/registry.hpp"
#include "shockgas/core/error.hpp"
#include "shockgas/core/interrupt.hpp"

namespace shockgas::app {

namespace fs = std::filesystem;

namespace {

// The records written with the particles' part (snapshots, space-time) are not
// needed later: only the final state (for the comparison) and the series stay.
void release_records(ParticleResults& p) {
  p.ensemble.first.snapshots = {};
  p.ensemble.first.spacetime = {};
  p.states = nullptr;
}

VariantResult reduce(const RunResults& r, nlohmann::ordered_json summary) {
  VariantResult v;
  v.summary = std::move(summary);
  if (r.particles) {
    v.t = r.particles->ensemble.t;
    v.T = r.particles->ensemble.T.mean;
    v.T_stderr = r.particles->ensemble.T.stderr_;
    v.histogram = r.particles->histogram;
    v.histogram_exact = r.particles->histogram_exact;
    if (r.particles->exact) v.temperature_amplitude_exact = r.particles->exact->temperature_amplitude;
  }
  return v;
}

std::string listed(const std::vector<std::string>& names) {
  std::string text;
  for (const auto& n : names) text += (text.empty() ? "" : ", ") + n;
  return text;
}

}  // namespace

// An input error located where the scene set its key (a file line or a --set);
// errors that carry their own place (a line of a bodies file) keep it.
InputError located(const InputError& e, const Scene& scene) {
  if (!e.where().empty()) return e;
  const auto it = scene.key_origin.find(e.key());
  return e.located(it != scene.key_origin.end() ? it->second : scene.path);
}

void draw_plots(const fs::path& dir, bool animation, ProgressBar& progress, const std::string& within) {
  progress.phase(animation ? "plots, animation" : "plots");
  const std::string said = make_plots(dir.string(), animation, within);
  progress.end_phase();
  progress.say(said);
}

// Only the continuum needs realization 0's bodies whole (its deposit); the
// particles and the writers draw them in chunks.
InitialCondition build_initial(const Scene& scene) {
  using Keep = InitialCondition::Keep;
  try {
    return InitialCondition(scene.initial, scene.has_continuum ? Keep::bodies : Keep::stream);
  } catch (const InputError& e) {
    throw located(e, scene);
  }
}

namespace {

// The largest speed of realization 0: of its bodies where they are held, else
// the bound of its velocities (uniform ones; Gaussian ones to 40 sd) [length/time].
double top_speed(const InitialCondition& initial) {
  if (initial.holds_bodies()) {
    double v = 0;
    for (const double u : initial.bodies().v) v = std::max(v, std::abs(u));
    return v;
  }
  const InitialParams& p = initial.params();
  return p.velocities == Velocities::gaussian ? 40 * p.amplitude : p.amplitude;
}

// Times whose travel t max|v| leaves the range of doubles, and a threshold
// whose cluster gap sqrt(delta t) does: refused before any work under the
// scene's key (the exact hull and the clusters refused them after the work,
// as "t" and "cluster.max_gap").
void check_reach(const Scene& scene, const InitialCondition& initial) {
  const double most = std::numeric_limits<double>::max() / 8, v = top_speed(initial),
               x = 2 * initial.length();
  const auto reach = [&](const std::string& key, double t) {
    require(v == 0 || t * v < most - x, key, t,
            "at most " + to_text((most - x) / v, 3) + " for these bodies (max |v| = " + to_text(v, 3) +
                "): x + t v must stay within the range of doubles");
  };
  if (scene.has_particles) {
    reach("particles.t_end", scene.particles.t_end);
    require(
        scene.particles.delta * scene.particles.t_end < most, "particles.delta", scene.particles.delta,
        "at most " + to_text(most / scene.particles.t_end, 3) +
            " for particles.t_end: the clusters' gap sqrt(delta t) must stay within the range of doubles");
  }
  if (scene.has_continuum) reach("continuum.t_end", scene.continuum_t_end());
}

}  // namespace

// Every solver's own limits (CFL bound, cells against nu, ...) are checked by its
// registered preflight, without solving, and the particle engine checks a
// requested schedule against the initial bodies, so that bad input stops the
// run before any work and before anything is written; so are times and
// thresholds beyond the range of doubles.
void preflight(const Scene& scene, const InitialCondition& initial) {
  try {
    check_reach(scene, initial);
    if (scene.has_particles && scene.particles.solver == particles::ParticleSolver::events &&
        scene.particles.schedule == particles::Schedule::windows)
      particles::check_schedule(initial, scene.particles);
    if (!scene.has_continuum) return;
    for (const auto& name : scene.continuum.solvers)
      continuum::preflight(name, initial.field(), scene.continuum, scene.continuum_t_end());
  } catch (const InputError& e) {
    throw located(e, scene);
  }
}

RunResults compute_parts(const Scene& scene, const InitialCondition& initial, ProgressBar& progress,
                         const PartSink& sink, const EnsembleSource& source) {
  RunResults r;
  r.scene = &scene;
  r.initial = &initial;
  r.shape = scene_shape(scene, initial);
  sink(r, Part::provenance);
  sink(r, Part::initial);
  if (scene.has_particles) {
    r.particles = run_particles(scene, initial, r.shape, progress, source);
    sink(r, Part::particles);
    sink(r, Part::analysis);
    if (scene.has_statistics) {
      progress.phase("statistics: the clusters of every realization at t_end");
      r.statistics = run_statistics_stage(scene, r.particles->ensemble);
    }
    release_records(*r.particles);
  }
  if (scene.has_continuum) {
    progress.phase("continuum: solving " + listed(scene.continuum.solvers));
    r.continuum = run_continuum(scene, initial, progress);
    sink(r, Part::continuum);
  }
  if (scene.has_compare && scene.has_continuum) {
    progress.phase("comparison: clusters against the shocks of " + scene.compare.solver);
    r.comparison = run_comparison(scene, initial, *r.particles, r.continuum);
    sink(r, Part::compare);
  }
  if (scene.output.animation) {
    progress.phase("frames: " + std::to_string(scene.output.animation_frames) + " for the animation");
    r.frames = run_frames(scene, initial, r.shape,
                          r.particles ? r.particles->frames : std::vector<particles::Snapshot>{}, progress);
    sink(r, Part::animation);
  }
  sink(r, Part::theory);  // where each law holds, to the time the data end
  progress.finish();
  return r;
}

VariantResult run_single(const Scene& scene, const InitialCondition& initial, const fs::path& dir,
                         const RunOptions& options, const PartSink& also, const EnsembleSource& source) {
  nlohmann::ordered_json summary;
  ProgressBar progress(options.progress, options.on_progress);
  const auto variant = scene.name.find('/');  // a sweep's variant: "<scene>/<label>"
  if (variant != std::string::npos) progress.name_phases(scene.name.substr(variant + 1));
  RunResults r;
  ResultContents written;  // what result.h5 holds, for result.xdmf and report.html
  {
    Hdf5File h5 = Hdf5File::create((dir / "result.h5").string());
    r = compute_parts(
        scene, initial, progress,
        [&](const RunResults& partial, Part part) {
          write_part(h5, partial, part);
          summarize_part(summary, partial, part);
          if (also) also(partial, part);
          throw_if_aborted();
        },
        source);
    progress.phase(r.statistics ? "writing result.h5, summary.json, statistics.h5, .csv, .md"
                                : "writing result.h5, summary.json");
    written = written_contents(h5, [](const std::string& path) { return path == "/animation/t"; });
    h5.close();
  }
  write_xdmf(dir.string(), written);
  write_file(dir / "summary.json", summary.dump(2) + "\n");
  if (r.statistics) write_statistics(dir, *r.statistics);
  if (options.plots && scene.output.plots)
    draw_plots(dir, scene.output.animation, progress,
               variant != std::string::npos ? dir.filename().string() : "");
  progress.end_phase();
  auto phases = progress.phase_times();
  if (r.particles)
    phases.insert(phases.begin(), {"particles: simulation", r.particles->ensemble.wall_seconds});
  const std::string report = report_text(r) + phase_times_text(phases);
  progress.phase("writing report.md, report.html, manifest.json");
  write_file(dir / "report.md", report);
  write_report_html(dir, summary, written);
  write_manifest(dir, scene.name);
  return reduce(r, std::move(summary));
}

std::string into_run_directory(RunDirectory& dir, const fs::path& out, const Scene& scene,
                               const RunOptions& options,
                               const std::function<void(const fs::path& staging)>& write) {
  try {
    write(dir.staging());
  } catch (const InputError& e) {  // a rule checked where the work starts (the engine's own)
    throw located(e, scene);
  }
  ProgressBar progress(options.progress);
  progress.phase("syncing, moving into " + out.string());
  dir.commit();
  return out.string();
}

}  // namespace shockgas::app
