// The frames of an animation (frames.hpp): the particles as clusters and every
// solver's fields at the frame times, and the evolution of the exact solver's.
#include <algorithm>
#include <limits>

#include "shockgas/app/output/frames.hpp"
#include "shockgas/app/output/theory_scopes.hpp"
#include "shockgas/app/run/progress_bar.hpp"
#include "shockgas/app/run/run_internal.hpp"
#include "shockgas/compare/snapshot_comparison.hpp"
#include "shockgas/compare/theory.hpp"
#include "shockgas/continuum/registry.hpp"
#include "shockgas/continuum/series.hpp"

namespace shockgas::app {

namespace {

// Each cluster (cluster_finder.hpp, the criteria of the comparison at t) as one
// body at its centre of mass.
Bodies clusters_of(const Scene& scene, const InitialCondition& initial, const particles::Snapshot& s) {
  const bool ring = scene.particles.geometry == particles::Geometry::ring;
  const double spacing = initial.length() / static_cast<double>(scene.initial.N);
  const auto criteria =
      compare::snapshot_params(scene.compare, scene.particles.r, scene.particles.delta, spacing, s.t)
          .clusters;
  Bodies out;
  for (const auto& c : particles::find_clusters(s.bodies, ring ? initial.length() : 0.0, criteria))
    out.push_back(c.x, c.v, c.m);
  return out;
}

// The exact solver if the scene runs it, else the first one.
std::size_t measured_solver(const std::vector<std::string>& solvers) {
  const auto it = std::find(solvers.begin(), solvers.end(), continuum::reference_solver_name());
  return it == solvers.end() ? 0 : static_cast<std::size_t>(it - solvers.begin());
}

// Where the amplitude's decay law holds (N-wave or sawtooth, theory_scope.hpp), its window's start; else 0.
double decay_fit_start(const Scene& scene, const compare::SceneShape& shape) {
  for (const compare::Law law : {compare::Law::n_wave_decay, compare::Law::sawtooth_decay})
    if (const compare::Scope s = compare::scope(law, shape, law_time(scene, law)); s.holds) return s.t_min;
  return 0.0;
}

}  // namespace

Frames run_frames(const Scene& scene, const InitialCondition& initial, const compare::SceneShape& shape,
                  const std::vector<particles::Snapshot>& snapshots, ProgressBar& progress) {
  Frames f;
  f.t = frame_times(scene);
  for (const auto& s : snapshots) {
    f.cluster_t.push_back(s.t);
    f.clusters.push_back(clusters_of(scene, initial, s));
  }
  f.breaking_time_theory = std::numeric_limits<double>::quiet_NaN();
  if (!scene.has_continuum) return f;
  for (const auto& name : scene.continuum.solvers) {
    progress.stage("frames/" + name);
    f.fields.push_back(continuum::solve_at_times(name, initial.field(), scene.continuum, f.t,
                                                 wall_limited(scene, name, progress.callback())));
    progress.finish();
  }
  const std::size_t k = measured_solver(scene.continuum.solvers);
  f.evolution_solver = scene.continuum.solvers[k];
  f.evolution =
      compare::analyse_field_evolution(f.fields[k], scene.compare.fit_window, decay_fit_start(scene, shape));
  f.breaking_time_theory = shape.breaking_time;  // NaN for data given as bodies
  return f;
}

}  // namespace shockgas::app
