#pragma once
// Shared by the unit and slow tests: the r = 0 engine against the exact hull
// (E, Rykov & Sinai 1996): the same cluster partition, positions and velocities
// equal to rounding.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "shockgas/core/initial_condition.hpp"
#include "shockgas/core/sticky_hull.hpp"
#include "shockgas/particles/simulate.hpp"

namespace shockgas::particles::testing {

// Compares the engine's snapshots with the hull at the same times. At r = 0 the
// threshold and the sub-threshold rule do not apply (collision.hpp): any delta
// gives the hull's clusters.
inline void expect_engine_matches_hull(std::size_t n, const std::string& positions,
                                       const std::string& geometry, const std::vector<double>& times,
                                       std::uint64_t seed, double delta = 0.0,
                                       Subthreshold subthreshold = Subthreshold::elastic) {
  InitialParams ip;
  ip.N = n;
  ip.positions = parse_enum<Positions>(positions, "initial.positions");
  ip.seed = seed;
  ip.remove_mean = geometry == "ring";  // the ring hull works in the centre-of-mass frame
  const Bodies initial = make_initial_bodies(ip);
  const double L = static_cast<double>(n);
  ParticleParams p;
  p.r = 0.0;
  p.delta = delta;
  p.subthreshold = subthreshold;
  p.geometry = parse_enum<Geometry>(geometry, "particles.geometry");
  p.t_end = times.back();
  p.samples = 1;
  p.clusters = false;
  p.snapshots = times;
  const RunResult run = simulate(initial, L, p);
  ASSERT_EQ(run.stop.reason, StopReason::completed);
  ASSERT_EQ(run.snapshots.size(), times.size());
  for (const Snapshot& snap : run.snapshots) {
    SCOPED_TRACE("t = " + std::to_string(snap.t));
    const Bodies exact = to_bodies(geometry == "ring" ? sticky_clusters_ring(initial, L, snap.t)
                                                      : sticky_clusters_line(initial, snap.t));
    const Bodies& engine = snap.bodies;
    ASSERT_EQ(engine.size(), exact.size());
    // Ring: a cluster at the seam may wrap to the other end in one of the two; align.
    const std::size_t k = engine.size();
    std::size_t shift = 0;
    if (geometry == "ring")
      for (std::size_t s : {std::size_t{0}, std::size_t{1}, k - 1})
        if (engine.m[s % k] == exact.m[0]) {
          shift = s % k;
          break;
        }
    // Positions: rounding of x + v t over the merges of a cluster; measured
    // differences <= 1e-15 L (N = 10^5, t <= 10^4), so 1e-12 L is a wide margin
    // that still fails on any wrong merge (which moves x by O(1)).
    const double x_tol = 1e-12 * L;
    // Velocities: mass-weighted means of O(1) values; measured <= 2.3e-16.
    const double v_tol = 1e-14;
    for (std::size_t c = 0; c < k; ++c) {
      const std::size_t e = (c + shift) % k;
      ASSERT_EQ(engine.m[e], exact.m[c]) << "cluster " << c;  // integer masses: exact
      double dx = std::abs(engine.x[e] - exact.x[c]);
      if (geometry == "ring") dx = std::min(dx, L - dx);
      EXPECT_LT(dx, x_tol) << "cluster " << c;
      EXPECT_NEAR(engine.v[e], exact.v[c], v_tol) << "cluster " << c;
    }
  }
}

}  // namespace shockgas::particles::testing
