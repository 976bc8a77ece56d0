#include <gtest/gtest.h>

#include <cmath>

#include "shockgas/compare/field_distance.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::compare {
namespace {

// A density shifted by a constant: the distance per unit length is the shift
// whatever the number of cells (the old sum |a - b| dx grew with the domain),
// and relative to the mass it is shift / mean density. Exact in binary.
TEST(FieldDistance, PerLengthAndRelativeToTheMassForADensity) {
  for (std::size_t cells : {4u, 4096u}) {
    const std::vector<double> exact(cells, 2.0), shifted(cells, 2.5);
    const L1Distance d = l1_distance(shifted, exact, L1Scale::absolute);
    EXPECT_EQ(d.per_length, 0.5);
    EXPECT_EQ(d.relative, 0.25);
  }
}

// All the mass moved to other cells: relative = 2, the largest possible for two
// densities of equal mass.
TEST(FieldDistance, DisjointDensitiesOfEqualMassAreTwoApart) {
  const std::vector<double> a{4, 0, 0, 0}, b{0, 0, 2, 2};
  EXPECT_EQ(l1_distance(a, b, L1Scale::absolute).relative, 2.0);
  EXPECT_EQ(l1_distance(a, b, L1Scale::absolute).per_length, 2.0);
}

// A velocity: relative to the reference's variation about its mean, so that a
// Galilean shift of both fields leaves it unchanged.
TEST(FieldDistance, VelocityIsRelativeToItsVariationAboutTheMean) {
  const std::vector<double> exact{1, -1, 1, -1}, field{0.5, -1, 1, -1};
  const L1Distance d = l1_distance(field, exact, L1Scale::about_mean);
  EXPECT_EQ(d.per_length, 0.125);
  EXPECT_EQ(d.relative, 0.125);
  std::vector<double> exact_shifted = exact, field_shifted = field;
  for (auto& v : exact_shifted) v += 10;
  for (auto& v : field_shifted) v += 10;
  const L1Distance s = l1_distance(field_shifted, exact_shifted, L1Scale::about_mean);
  EXPECT_EQ(s.per_length, d.per_length);
  EXPECT_EQ(s.relative, d.relative);
}

TEST(FieldDistance, AConstantReferenceHasNoRelativeScale) {
  EXPECT_TRUE(std::isnan(l1_distance({1, 2}, {3, 3}, L1Scale::about_mean).relative));
  EXPECT_THROW(l1_distance({1, 2, 3}, {3, 3}, L1Scale::absolute), InputError);
  EXPECT_THROW(l1_distance({}, {}, L1Scale::absolute), InputError);
}

}  // namespace
}  // namespace shockgas::compare
