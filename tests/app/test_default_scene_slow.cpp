// The default scene's clusters in time (data/scenes/default.toml, as a user
// runs it: /particles/n_clusters, the clusters of at least
// particles.min_cluster_particles = k particles) follow the exact count of the
// shocks heavier than k - 1/2 particles of Burgers turbulence from the same
// white noise (/particles/analysis/n_clusters_exact) from t = 10^3 on: against
// the exact sticky gas of the same starts (the hull at r = 0, realization by
// realization), and against the exact law.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "shockgas/app/input/scene_parser.hpp"
#include "shockgas/compare/shock_mass_law.hpp"
#include "shockgas/compare/white_noise_references.hpp"
#include "shockgas/particles/cluster_finder.hpp"
#include "shockgas/particles/simulate.hpp"

namespace shockgas::app {
namespace {

const char* kDefault = SHOCKGAS_SOURCE_DIR "/data/scenes/default.toml";

// Each realization's count at the samples, realizations 0 .. R - 1 of the scene's start.
std::vector<std::vector<double>> counts(const Scene& scene, const particles::ParticleParams& p, std::size_t R,
                                        std::vector<double>& t) {
  const InitialCondition initial(scene.initial);
  std::vector<std::vector<double>> n;
  for (std::size_t k = 0; k < R; ++k) {
    const particles::RunResult run = particles::simulate(initial, k, p);
    t = run.series.t;
    n.push_back(run.series.n_clusters);
  }
  return n;
}

struct Mean {
  double value = 0, error = 0;  // mean over realizations and its standard error
};

Mean mean_of(const std::vector<double>& x) {
  const double n = static_cast<double>(x.size());
  Mean m;
  for (double v : x) m.value += v / n;
  for (double v : x) m.error += (v - m.value) * (v - m.value);
  m.error = std::sqrt(m.error / (n - 1) / n);
  return m;
}

std::vector<double> column(const std::vector<std::vector<double>>& rows, std::size_t j) {
  std::vector<double> c;
  for (const auto& r : rows) c.push_back(r[j]);
  return c;
}

// 16 realizations of the scene (its 2 give the curve; more resolve it): at every
// sample from t = 10^3 on, the gas's mean count lies within 3 standard errors
// of the sticky gas's from the same starts (the paired difference; measured: at
// most 1.6) and of the exact law (measured: at most 2.5, the late samples 2-4 %
// below, where the sticky gas of these starts is 2 % below too; Student's t of 15
// degrees of freedom exceeds 3 with probability 0.9 %). With delta = 1e-2 (the
// scene before) the same count was 8.5-22.5 paired standard errors below the
// sticky gas's and 8.6-18 below the law (0.82-0.93 of it), and with k = 2 the pairs of a few particles keep
// it 4-12 % short (docs/validate.md).
TEST(DefaultScene, ClustersInTimeFollowTheExactShockCountFromTenToTheThreeOn) {
  const Scene scene = load_scene(kDefault);
  ASSERT_GT(scene.particles.min_cluster_particles, 2u);  // the scene states its mass threshold
  particles::ParticleParams p = scene.particles;
  p.histogram_bins = 0, p.spacetime = false;  // neither changes the count
  p.final_clusters = particles::ClusterRecord::never;
  p.threads = 0;
  constexpr std::size_t R = 16;
  std::vector<double> t;
  const auto gas = counts(scene, p, R, t);
  particles::ParticleParams sticky = p;
  sticky.r = 0.0;
  sticky.solver = particles::ParticleSolver::hull;
  const auto hull = counts(scene, sticky, R, t);
  const compare::WhiteNoiseReferences w = *compare::white_noise_references(scene.initial);
  const double lightest =
      particles::MultiParticleRule(w.density * w.length / static_cast<double>(scene.initial.N),
                                   scene.particles.min_cluster_particles)
          .heavy_mass();
  std::size_t compared = 0;
  for (std::size_t j = 0; j < t.size(); ++j) {
    if (t[j] < 1e3 * (1 - 1e-12)) continue;
    SCOPED_TRACE("t = " + std::to_string(t[j]));
    const Mean n = mean_of(column(gas, j));
    std::vector<double> paired;
    for (std::size_t k = 0; k < R; ++k) paired.push_back(gas[k][j] - hull[k][j]);
    const Mean d = mean_of(paired);
    EXPECT_LT(std::abs(d.value), 3 * d.error) << n.value << " against the sticky gas's " << n.value - d.value;
    const double exact = compare::expected_shocks_above(lightest, w.D, w.length, w.density, t[j]);
    EXPECT_LT(std::abs(n.value - exact), 3 * n.error) << n.value << " +- " << n.error << " against " << exact;
    ++compared;
  }
  EXPECT_EQ(compared, 10u);  // the samples of [10^3, 10^4] of 40 log-spaced in [1, 10^4]
}

}  // namespace
}  // namespace shockgas::app
