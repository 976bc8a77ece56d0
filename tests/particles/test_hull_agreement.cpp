#include <algorithm>

#include "hull_agreement.hpp"
#include "shockgas/core/error.hpp"
#include "shockgas/particles/params.hpp"

namespace shockgas::particles {
namespace {

const std::vector<double> kTimes = {1.0, 10.0, 100.0, 1000.0};

TEST(HullAgreement, LatticeOnALine) {
  testing::expect_engine_matches_hull(3000, "lattice", "line", kTimes, 1);
}
TEST(HullAgreement, RandomOnALine) { testing::expect_engine_matches_hull(3000, "random", "line", kTimes, 2); }
TEST(HullAgreement, LatticeOnARing) {
  testing::expect_engine_matches_hull(3000, "lattice", "ring", kTimes, 3);
}
TEST(HullAgreement, RandomOnARing) { testing::expect_engine_matches_hull(3000, "random", "ring", kTimes, 4); }

// r = 0 is the sticky gas whatever the threshold: with delta = 0.3 most collisions
// after t ~ 10 are slower than delta (velocities ~ t^(-1/3)), and an elastic bounce
// there would leave the hull's partition.
TEST(HullAgreement, AThresholdDoesNotApplyAtRZero) {
  testing::expect_engine_matches_hull(3000, "random", "ring", kTimes, 5, 0.3, Subthreshold::elastic);
  testing::expect_engine_matches_hull(3000, "random", "line", kTimes, 6, 1e-2, Subthreshold::elastic);
  testing::expect_engine_matches_hull(3000, "lattice", "ring", kTimes, 7, 0.3, Subthreshold::sticky);
}

// Bodies that meet exactly at an output time have collided by then in both:
// x = i, v = +1, -1, +1, ... pairs meet at t = 1/2 (exact in doubles) and stop.
TEST(HullAgreement, ACollisionExactlyAtTheOutputTimeIsMadeByBoth) {
  for (const Geometry geometry : {Geometry::line, Geometry::ring}) {
    Bodies b;
    for (int i = 0; i < 2000; ++i) b.push_back(i + 0.25, i % 2 == 0 ? 1.0 : -1.0, 1.0);
    const double L = 2000.0;
    ParticleParams p;
    p.r = 0.0;
    p.geometry = geometry;
    p.t_end = 0.5;
    p.samples = 1;
    p.clusters = false;
    p.snapshots = {0.25, 0.5};
    const RunResult run = simulate(b, L, p);
    ASSERT_EQ(run.snapshots.size(), 2u);
    for (const Snapshot& snap : run.snapshots) {
      const Bodies exact = to_bodies(geometry == Geometry::ring ? sticky_clusters_ring(b, L, snap.t)
                                                                : sticky_clusters_line(b, snap.t));
      EXPECT_EQ(snap.bodies.size(), exact.size()) << "t = " << snap.t;
    }
    EXPECT_EQ(run.snapshots[1].bodies.size(), 1000u);  // every pair met at t = 1/2
  }
  // At t = 0: coincident bodies that approach have met, those that separate have not.
  Bodies b;
  b.push_back(1.0, 1.0, 1.0);
  b.push_back(1.0, -1.0, 1.0);
  b.push_back(2.0, -1.0, 1.0);
  b.push_back(2.0, 1.0, 1.0);
  EXPECT_EQ(sticky_clusters_line(b, 0.0).size(), 3u);
}

TEST(HullModel, SameObservablesAsTheEngine) {
  InitialParams ip;
  ip.N = 2000;
  ip.seed = 5;
  ip.remove_mean = true;
  const Bodies initial = make_initial_bodies(ip);
  ParticleParams p;
  p.r = 0.0;
  p.delta = 0.0;
  p.t_end = 500.0;
  p.samples = 8;
  p.histogram_bins = 20;
  const RunResult events = simulate(initial, 2000.0, p);
  p.solver = ParticleSolver::hull;
  const RunResult hull = simulate(initial, 2000.0, p);
  ASSERT_EQ(hull.series.size(), 8u);
  ASSERT_EQ(events.series.size(), 8u);
  for (std::size_t k = 0; k < 8; ++k) {
    EXPECT_EQ(hull.series.n_bodies[k], events.series.n_bodies[k]);  // same partition
    EXPECT_EQ(hull.series.merges[k], events.series.merges[k]);
    EXPECT_EQ(hull.series.n_clusters[k], events.series.n_clusters[k]);  // same merged bodies
    // Mean-square velocities of O(1) values: rounding ~1e-15, margin for the sum.
    EXPECT_NEAR(hull.series.T[k], events.series.T[k], 1e-12);
    EXPECT_NEAR(hull.series.dissipated[k], events.series.dissipated[k], 1e-9);
  }
  ASSERT_EQ(hull.histogram.density.size(), events.histogram.density.size());
  EXPECT_EQ(hull.final_state.size(), events.final_state.size());
  // The bodies are the clusters; those of two or more unit masses are counted.
  const auto merged =
      std::count_if(hull.final_state.m.begin(), hull.final_state.m.end(), [](double m) { return m >= 2.0; });
  EXPECT_EQ(hull.series.n_clusters.back(), static_cast<double>(merged));
  EXPECT_LT(hull.series.n_clusters.front(), hull.series.n_bodies.front());  // lone particles were left out
}

// The hull has no collisions to count nor safe points: the engine's limits are
// refused with it (found: max_collisions = 5000 was ignored, stop = completed).
TEST(HullModel, TheEnginesLimitsAreRefused) {
  ParticleParams p;
  p.r = 0.0;
  p.solver = ParticleSolver::hull;
  validate(p);
  p.max_collisions = 5000;
  try {
    validate(p);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "particles.max_collisions");
  }
  p.max_collisions = 0;
  p.max_wall_seconds = 10.0;
  EXPECT_THROW(validate(p), InputError);
}

}  // namespace
}  // namespace shockgas::particles
