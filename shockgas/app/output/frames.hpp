#pragma once
// The frames of an animation ([output] animation = true): the particles and
// every continuum solver's fields at the frame times, from the same start, and
// what the exact solver's fields say of the wave's evolution
// (shockgas/compare/field_evolution.hpp). Recorded only when a scene asks for an
// animation; written under /animation (output_frames.cpp) and drawn by
// plots/animate.py from result.h5 alone.
#include <string>
#include <vector>

#include "shockgas/app/scene/scene.hpp"
#include "shockgas/compare/field_evolution.hpp"
#include "shockgas/compare/theory_scope.hpp"
#include "shockgas/continuum/field.hpp"
#include "shockgas/core/bodies.hpp"
#include "shockgas/core/initial_condition.hpp"
#include "shockgas/particles/run_result.hpp"

namespace shockgas::app {

class ProgressBar;

struct Frames {
  std::vector<double> t;          // frame times [time]
  std::vector<double> cluster_t;  // the frame times the particles reached [time]
  std::vector<Bodies> clusters;   // realization 0's clusters at each of cluster_t
  std::vector<std::vector<continuum::ContinuumResult>> fields;  // per solver of continuum.solvers, per frame
  std::string evolution_solver;                                 // whose fields the evolution measures
  compare::FieldEvolution evolution;
  double breaking_time_theory = 0;  // 1 / max(-v0') for pointwise data; NaN for particle data
};

// The frame times of a scene: output.animation_frames times, the first at 0, the
// last at the run's end (particles.t_end, else continuum.t_end).
std::vector<double> frame_times(const Scene& scene);

// The particle parameters a run of the scene simulates with: the scene's, with
// the frame times added to the snapshot times when it asks for an animation.
// Every realization runs with them, wherever it runs (one process, a rank, a
// shard), so that all agree bit for bit.
particles::ParticleParams particle_params(const Scene& scene);

// The rules of [output] animation between keys; InputError naming the key.
void check_animation(const Scene& scene);

// The frames of a run: the particles' snapshots at frame_times (`snapshots`,
// those reached) as clusters, each solver's fields at frame_times
// (shockgas/continuum/series.hpp), and the evolution of the exact solver's fields (else
// the first solver's).
// shape: scene_shape(scene, initial) (theory_scopes.hpp), computed once per run.
Frames run_frames(const Scene& scene, const InitialCondition& initial, const compare::SceneShape& shape,
                  const std::vector<particles::Snapshot>& snapshots, ProgressBar& progress);

}  // namespace shockgas::app
