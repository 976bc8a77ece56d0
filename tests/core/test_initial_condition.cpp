// The initial condition built once (shockgas/core/initial_condition.hpp): realization 0
// is what every model sees, other realizations are the seeded draws.
#include <gtest/gtest.h>

#include "shockgas/core/error.hpp"
#include "shockgas/core/initial_condition.hpp"

namespace shockgas {
namespace {

void expect_same(const Bodies& a, const Bodies& b) {
  EXPECT_EQ(a.x, b.x);
  EXPECT_EQ(a.v, b.v);
  EXPECT_EQ(a.m, b.m);
}

TEST(InitialCondition, RealizationsAreTheSeededDraws) {
  InitialParams p;
  p.N = 100;
  p.positions = Positions::random;
  p.seed = 7;
  const InitialCondition ic(p);
  expect_same(ic.bodies(), make_initial_bodies(p, 0));
  expect_same(ic.realization(0), ic.bodies());
  expect_same(ic.realization(3), make_initial_bodies(p, 3));
  EXPECT_NE(ic.realization(3).v, ic.bodies().v);
  // The continuum sees realization 0 as point masses.
  ASSERT_TRUE(ic.field().from_bodies());
  expect_same(ic.field().bodies, ic.bodies());
  EXPECT_EQ(ic.length(), 100.0);
}

TEST(InitialCondition, ExpressionsGiveTheFieldAndALatticeOfBodies) {
  InitialParams p;
  p.N = 64;
  p.velocities = Velocities::expression;
  p.v0 = "sin(2*pi*x)";
  p.rho0 = "2";
  const InitialCondition ic(p);
  EXPECT_FALSE(ic.field().from_bodies());
  EXPECT_EQ(ic.field().v0(0.25), 1.0);  // sin(pi/2), exact in double
  expect_same(ic.bodies(), make_initial_bodies(p, 0));
  expect_same(ic.realization(5), ic.bodies());  // no randomness in an expression
}

TEST(InitialCondition, BadParametersAreRefusedWhenBuilt) {
  InitialParams p;
  p.N = 1;
  try {
    InitialCondition ic(p);
    FAIL() << "N = 1 accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "initial.N");
  }
}

}  // namespace
}  // namespace shockgas
