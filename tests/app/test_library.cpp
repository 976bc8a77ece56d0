// shockgas as a library: the umbrella header is enough to simulate a gas, take
// its exact solution and compare it with a registered solver.
#include <gtest/gtest.h>

#include "shockgas/shockgas.hpp"

namespace shockgas {
namespace {

TEST(Library, UmbrellaHeaderRunsTheEngineTheHullAndASolver) {
  InitialParams ip;
  ip.N = 2000;
  ip.seed = 3;
  ip.remove_mean = true;  // the ring hull works in the centre-of-mass frame
  const InitialCondition initial(ip);
  particles::ParticleParams p;
  p.r = 0;  // sticky: the engine must agree with the exact hull
  p.t_end = 50;
  p.samples = 1;
  const particles::RunResult run = particles::simulate(initial.bodies(), initial.length(), p);
  const Bodies exact = to_bodies(sticky_clusters_ring(initial.bodies(), initial.length(), p.t_end));
  EXPECT_EQ(run.final_state.size(), exact.size());  // the same cluster partition (HullAgreement.*)
  continuum::ContinuumParams cp;
  cp.cells = 2000;
  const auto field = continuum::solve(continuum::reference_solver_name(), initial.field(), cp, p.t_end);
  EXPECT_TRUE(field.has_shocks);
  // r = 0: every cluster of two or more bodies is a shock of the exact solver (ExactStickyMatch.*).
  std::size_t clusters = 0;
  for (double m : exact.m) clusters += m >= 2;
  EXPECT_EQ(field.shocks.size(), clusters);
}

}  // namespace
}  // namespace shockgas
