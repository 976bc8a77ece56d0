// particles.solver = "auto": the exact hull where it applies (r = 0, no engine
// limit), the event engine otherwise; what it chose runs, and is said.
#include <gtest/gtest.h>

#include "shockgas/core/initial_condition.hpp"
#include "shockgas/particles/params.hpp"
#include "shockgas/particles/simulate.hpp"

namespace shockgas::particles {
namespace {

ParticleParams automatic(double r) {
  ParticleParams p;
  p.solver = ParticleSolver::automatic;
  p.r = r;
  p.t_end = 200.0;
  p.samples = 6;
  return p;
}

TEST(AutoSolver, ChoosesTheHullForTheStickyGas) {
  const ParticleParams p = automatic(0.0);
  validate(p);
  EXPECT_EQ(chosen_solver(p), ParticleSolver::hull);
  EXPECT_NE(solver_choice_note(p).find("the exact hull"), std::string::npos) << solver_choice_note(p);
}

TEST(AutoSolver, ChoosesTheEngineForAnInelasticGas) {
  const ParticleParams p = automatic(0.5);
  validate(p);  // "hull" would be refused with r = 0.5; "auto" is not
  EXPECT_EQ(chosen_solver(p), ParticleSolver::events);
  EXPECT_NE(solver_choice_note(p).find("the event engine, as particles.r = 0.5 > 0"), std::string::npos)
      << solver_choice_note(p);
}

// The hull has no collisions to count nor safe points to stop at: a limit asks for the engine.
TEST(AutoSolver, ChoosesTheEngineWhenALimitIsSet) {
  ParticleParams p = automatic(0.0);
  p.max_collisions = 100;
  validate(p);
  EXPECT_EQ(chosen_solver(p), ParticleSolver::events);
  p.max_collisions = 0;
  p.max_wall_seconds = 5;
  EXPECT_EQ(chosen_solver(p), ParticleSolver::events);
  EXPECT_NE(solver_choice_note(p).find("limit"), std::string::npos) << solver_choice_note(p);
}

TEST(AutoSolver, AnyOtherSolverIsAsGivenWithoutANote) {
  ParticleParams p = automatic(0.0);
  for (ParticleSolver s : {ParticleSolver::events, ParticleSolver::hull}) {
    p.solver = s;
    EXPECT_EQ(chosen_solver(p), s);
    EXPECT_EQ(solver_choice_note(p), "");
  }
}

// What runs is what was chosen, to the bit: the same series and final state.
TEST(AutoSolver, RunsTheChosenSolverBitForBit) {
  InitialParams ip;
  ip.N = 1500;
  ip.seed = 9;
  const Bodies initial = make_initial_bodies(ip);
  for (double r : {0.0, 0.5}) {
    ParticleParams p = automatic(r);
    const RunResult chosen = simulate(initial, 1500.0, p);
    p.solver = r == 0.0 ? ParticleSolver::hull : ParticleSolver::events;
    const RunResult explicit_solver = simulate(initial, 1500.0, p);
    EXPECT_EQ(chosen.series.T, explicit_solver.series.T) << "r = " << r;
    EXPECT_EQ(chosen.series.n_bodies, explicit_solver.series.n_bodies) << "r = " << r;
    EXPECT_EQ(chosen.final_state.x, explicit_solver.final_state.x) << "r = " << r;
    EXPECT_EQ(chosen.final_state.v, explicit_solver.final_state.v) << "r = " << r;
  }
}

}  // namespace
}  // namespace shockgas::particles
