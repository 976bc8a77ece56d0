// Stage 1: the particle gas (an ensemble of event-driven or exact-hull runs from
// the scene's initial condition), and what it shows alone: the cooling law and
// the scaled velocity distribution (shockgas/compare/particle_analysis.hpp), with the
// exact laws of a white-noise start beside them (shockgas/compare/white_noise_references.hpp).
// An animation adds its frame times to realization 0's snapshots (frames.hpp).
#include <algorithm>

#include "shockgas/app/output/frames.hpp"
#include "shockgas/app/output/run_results.hpp"
#include "shockgas/app/output/theory_scopes.hpp"
#include "shockgas/app/records/state_file.hpp"
#include "shockgas/app/run/progress_bar.hpp"
#include "shockgas/compare/cluster_velocity_law.hpp"
#include "shockgas/compare/heaviest.hpp"
#include "shockgas/compare/shock_mass_law.hpp"
#include "shockgas/compare/snapshot_comparison.hpp"
#include "shockgas/compare/sticky_same_starts.hpp"
#include "shockgas/compare/white_noise_references.hpp"
#include "shockgas/core/cores.hpp"
#include "shockgas/core/interrupt.hpp"
#include "shockgas/particles/cluster_finder.hpp"

namespace shockgas::app {

namespace {

// The exact expected number of shocks heavier than the lightest cluster the
// time series counts (MultiParticleRule: (k - 1/2) M / N, k =
// particles.min_cluster_particles), at each sample time.
std::vector<double> exact_cluster_counts(const compare::WhiteNoiseReferences& w, const std::vector<double>& t,
                                         const Scene& scene) {
  const double mean_mass = w.density * w.length / static_cast<double>(scene.initial.N);
  const double lightest =
      particles::MultiParticleRule(mean_mass, scene.particles.min_cluster_particles).heavy_mass();
  return compare::expected_shocks_above(lightest, w.D, w.length, w.density, t);
}

bool contains(const std::vector<double>& times, double t) {
  return std::find(times.begin(), times.end(), t) != times.end();
}

// The snapshots at frame times go to r.frames; the scene's own stay.
void split_frames(ParticleResults& r, const Scene& scene, const std::vector<double>& frames) {
  auto& snaps = r.ensemble.first.snapshots;
  std::vector<particles::Snapshot> own;
  for (auto& s : snaps) {
    if (contains(frames, s.t)) r.frames.push_back(s);
    if (contains(scene.particles.snapshots, s.t)) own.push_back(std::move(s));
  }
  snaps = std::move(own);
}

// The heaviest cluster of realization 0's final state: as its states file
// holds it (written as the state went by), else found in the state, held or
// read from that file in chunks.
std::optional<HeaviestCluster> heaviest_cluster(const ParticleResults& r, const Scene& s,
                                                const InitialCondition& initial) {
  const auto& end = r.ensemble.first;
  if (r.states) {
    if (auto h = r.states->heaviest_cluster()) return h;
    if (const auto* kept = r.states->final_state())
      return heaviest_final_cluster(s, initial.length(), end.stop.time, *kept);
    return std::nullopt;
  }
  return heaviest_final_cluster(s, initial.length(), end.stop.time, particles::BodiesReader(end.final_state));
}

// The fitted exponent against the exact sticky gas from the same starts, where
// that gas is cheap (sticky_same_starts.hpp) and T was fitted.
std::optional<compare::PairedExponents> same_starts_exponents(const ParticleResults& r, const Scene& scene,
                                                              const InitialCondition& initial) {
  if (!r.cooling.fit || !compare::same_starts_apply(scene.particles, scene.initial.N)) return std::nullopt;
  try {
    return compare::jackknife_paired_T_exponents(r.ensemble.t, r.ensemble.T_by_realization,
                                                 compare::sticky_T_rows(initial, scene.particles),
                                                 r.cooling.fit->t_min, r.cooling.fit->t_max);
  } catch (const InputError&) {
    return std::nullopt;  // the sticky gas's T cannot be fitted on the window (no finite exponent)
  }
}

}  // namespace

ParticleResults run_particles(const Scene& scene, const InitialCondition& initial,
                              const compare::SceneShape& shape, ProgressBar& progress,
                              const EnsembleSource& source) {
  ParticleResults r;
  // A phase of progress, until compute_parts starts the next one.
  const char* analysis = "particles: analysis, writing result.h5";
  if (source) {
    progress.phase(analysis);
    ComputedEnsemble computed = source(scene);
    r.ensemble = std::move(computed.ensemble);
    r.parallel = computed.parallel;
    r.states = std::move(computed.states);
  } else {
    progress.stage("particles", scene.particles.realizations);
    r.ensemble = particles::run_ensemble(initial, particle_params(scene), progress.callback());
    progress.finish();
    progress.phase(analysis);
    r.parallel.threads = resolved_threads(scene.particles.threads);
  }
  // Stopped at a safe point on a checkpoint request: nothing is written (no
  // checkpoint is kept yet), the run ends as interrupted.
  for (const particles::RunStop& stop : r.ensemble.stops)
    if (stop.reason == particles::StopReason::interrupted) throw Interrupted(interrupt_signal());
  if (scene.output.animation) split_frames(r, scene, frame_times(scene));
  r.heaviest = heaviest_cluster(r, scene, initial);
  const auto& h = r.ensemble.first.histogram;
  if (h.bins > 0) r.histogram = {h.zmax, h.bins, h.t, r.ensemble.histogram};
  const compare::Scope fit = compare::cooling_fit_scope(shape, scene.particles.t_end);
  r.cooling = compare::analyse_cooling(r.ensemble.t, r.ensemble.T.mean, scene.particles.r, fit.t_min,
                                       fit.t_max, fit.holds ? "" : fit.reason);
  r.distribution = compare::analyse_velocity_distribution(r.histogram, scene.compare.distribution_t_min);
  r.exact = compare::white_noise_references(scene.initial);
  if (r.exact && r.histogram.bins > 0)
    r.histogram_exact = compare::cluster_law_on_bins(r.histogram.edges(), r.exact->D);
  // The exponent's error on the fit's window where T was fitted (none: an empty one); every other
  // error either way.
  const compare::PowerLawFit fitted = r.cooling.fit.value_or(compare::PowerLawFit{});
  r.errors = compare::jackknife_analysis(
      r.ensemble.t, r.ensemble.T_by_realization, scene.particles.r, fitted.t_min, fitted.t_max, r.histogram,
      r.ensemble.histogram_by_realization, scene.compare.distribution_t_min);
  if (r.exact && scene.particles.clusters)
    r.n_clusters_exact = exact_cluster_counts(*r.exact, r.ensemble.t, scene);
  r.same_starts = same_starts_exponents(r, scene, initial);
  return r;
}

}  // namespace shockgas::app
