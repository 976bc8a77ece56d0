// The collision rule against hand-computed outcomes.
#include <gtest/gtest.h>

#include "shockgas/particles/collision.hpp"

namespace shockgas::particles {
namespace {

// Values below are exact in binary (halves, quarters), so results are exact
// unless noted; tolerances of 1e-15 cover one rounding of O(1) numbers.
constexpr double kRound = 1e-15;

TEST(Collision, EqualMassesHalfRestitution) {
  double v = 1.0, u = -1.0;  // g = 2; dv = (1 + 1/2) g / 2 = 1.5
  const double lost = bounce_equal(v, u, 1.0, 0.5);
  EXPECT_DOUBLE_EQ(v, -0.5);
  EXPECT_DOUBLE_EQ(u, 0.5);
  EXPECT_DOUBLE_EQ(lost, 0.25 * (1 - 0.25) * 4);  // (1 - r^2) mu g^2 / 2, mu = 1/2
}

TEST(Collision, UnequalMassesKeepMomentumAndMapApproachSpeed) {
  // mL = 1, mR = 3, v = 2, u = 0, r = 1/2: v' = 2 - 1.5 * 3/4 * 2 = -0.25, u' = 0 + 1.5 * 1/4 * 2 = 0.75.
  double v = 2.0, u = 0.0;
  const double lost = bounce(v, u, 1.0, 3.0, 0.5);
  EXPECT_NEAR(v, -0.25, kRound);
  EXPECT_NEAR(u, 0.75, kRound);
  EXPECT_NEAR(1.0 * v + 3.0 * u, 2.0, kRound);  // momentum
  EXPECT_NEAR(v - u, -0.5 * 2.0, kRound);       // g -> -r g
  // Energy: 2 before, (0.0625 + 3 * 0.5625) / 2 = 0.875 after.
  EXPECT_NEAR(lost, 2.0 - 0.875, kRound);
}

TEST(Collision, ElasticEqualMassesExchangeVelocities) {
  double v = 0.75, u = -0.25;
  EXPECT_EQ(bounce_equal(v, u, 1.0, 1.0), 0.0);
  EXPECT_DOUBLE_EQ(v, -0.25);
  EXPECT_DOUBLE_EQ(u, 0.75);
}

TEST(Collision, MergeKeepsMassAndMomentum) {
  // mL = 2, v = 1; mR = 1, u = -2: M = 3, V = 0; lost = mu g^2 / 2 = (2/3) * 9 / 2 = 3.
  const Merged m = merge(1.0, -2.0, 2.0, 1.0);
  EXPECT_DOUBLE_EQ(m.m, 3.0);
  EXPECT_DOUBLE_EQ(m.v, 0.0);
  EXPECT_NEAR(m.dissipated, 3.0, 4 * kRound);
}

TEST(Collision, ClassifyByThresholdAndRestitution) {
  const CollisionRule elastic_sub{0.5, 0.1, false};
  EXPECT_EQ(elastic_sub.classify(0.05), CollisionKind::elastic);
  EXPECT_EQ(elastic_sub.classify(0.1), CollisionKind::inelastic);  // g < delta is strict
  EXPECT_EQ(elastic_sub.restitution(CollisionKind::elastic), 1.0);
  EXPECT_FALSE(elastic_sub.can_merge());

  const CollisionRule sticky_sub{0.5, 0.1, true};
  EXPECT_EQ(sticky_sub.classify(0.05), CollisionKind::merge);
  EXPECT_TRUE(sticky_sub.can_merge());

  const CollisionRule aggregation{0.0, 0.0, false};
  EXPECT_EQ(aggregation.classify(1e-300), CollisionKind::merge);
  EXPECT_TRUE(aggregation.can_merge());

  // r = 0 merges every collision: the threshold and its rule do not apply.
  for (const bool sticky : {false, true}) {
    const CollisionRule sticky_gas{0.0, 0.1, sticky};
    EXPECT_TRUE(sticky_gas.merges_only());
    EXPECT_EQ(sticky_gas.classify(0.05), CollisionKind::merge);
    EXPECT_EQ(sticky_gas.classify(0.5), CollisionKind::merge);
  }
  EXPECT_FALSE(sticky_sub.merges_only());
}

}  // namespace
}  // namespace shockgas::particles
