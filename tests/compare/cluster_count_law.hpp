#pragma once
// The count of clusters in time (/particles/n_clusters: the clusters of two or
// more particles, MultiParticleRule) against the exact count of shocks of
// Burgers turbulence from the same white noise (white_noise_references.hpp).
// The exact count C t^(-2/3) includes the many shocks lighter than a particle
// (N(mu) ~ (2 / pi)^(1/2) mu^(-1/2), shock_mass_law.hpp: 9 % of all at t = 10^3,
// where a = (4 D t^2)^(1/3) = 110 spacings), which a lattice gas cannot hold; the
// clusters of two or more particles are the shocks heavier than 1.5 particles,
// (L / a) int_{1.5 / (rho a)} N(mu) dmu. Shared by the fast test (r = 0) and
// the slow one (r = 0.5).
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>

#include "shockgas/compare/shock_mass_law.hpp"
#include "shockgas/compare/white_noise_references.hpp"
#include "shockgas/particles/simulate.hpp"

namespace shockgas::compare::testing {

// White noise on a lattice, as data/scenes/default.toml starts: N unit masses,
// velocities uniform in [-1, 1] (D = 1/3).
inline InitialParams white_noise(std::size_t N) {
  InitialParams p;
  p.N = N;
  p.positions = Positions::lattice;
  p.velocities = Velocities::uniform;
  p.seed = 1;
  return p;
}

// C t^(-2/3): every shock.
inline double all_shocks(const WhiteNoiseReferences& w, double t) {
  return w.shock_count_coefficient * std::pow(t, -2.0 / 3.0);
}

// The shocks heavier than 1.5 particles (unit masses): the law's count above
// a mass (ShockMassLaw.ShocksAboveAMassAreTheBinsAboveIt holds it to its bins).
inline double shocks_of_two_or_more(const WhiteNoiseReferences& w, double t) {
  return expected_shocks_above(1.5, w.D, w.length, w.density, t);
}

// The ensemble's count at its samples from t_from on against the exact count of
// shocks heavier than 1.5 particles: within `z` standard errors of the
// ensemble mean (fixed seeds: the same numbers on every run). Returns how many
// samples were compared.
inline std::size_t expect_counts_the_shocks(const particles::EnsembleResult& e, const WhiteNoiseReferences& w,
                                            double t_from, double z) {
  std::size_t compared = 0;
  for (std::size_t k = 0; k < e.t.size(); ++k) {
    if (e.t[k] < t_from) continue;
    const double se = e.n_clusters.stderr_[k];
    EXPECT_GT(se, 0.0) << "t = " << e.t[k];
    EXPECT_NEAR(e.n_clusters.mean[k], shocks_of_two_or_more(w, e.t[k]), z * se) << "t = " << e.t[k];
    ++compared;
  }
  return compared;
}

}  // namespace shockgas::compare::testing
