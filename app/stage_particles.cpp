// Stage 1: the particle gas (an ensemble of event-driven or exact-hull runs from
// the scene's initial condition), and what it shows alone: the cooling law and
// the scaled velocity distribution (compare/particle_analysis.hpp).
#include "progress_bar.hpp"
#include "run_results.hpp"

namespace shockgas::app {

ParticleResults run_particles(const Scene& scene, const InitialCondition& initial, ProgressBar& progress) {
  progress.stage("particles");
  ParticleResults r;
  r.ensemble = particles::run_ensemble(initial, scene.particles, progress.callback());
  progress.finish();
  const auto& h = r.ensemble.first.histogram;
  if (h.bins > 0) r.histogram = {h.zmax, h.bins, h.t, r.ensemble.histogram};
  r.cooling = compare::analyse_cooling(r.ensemble.t, r.ensemble.T.mean, scene.particles.r,
                                       scene.particles.t_end, scene.compare.fit_window);
  r.distribution = compare::analyse_velocity_distribution(r.histogram, scene.compare.distribution_t_min);
  return r;
}

}  // namespace shockgas::app
