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

// A delta-shock (all the mass in one cell) one cell off: the densities share no
// cell, so L1 says the whole mass is misplaced (2 of at most 2), while the mass
// moved 1 cell of n: W1 / L = 1 / n exactly (cell averages, M at the midpoints).
TEST(FieldDistance, ADeltaShockOneCellOffIsOneCellAwayInMassDistance) {
  constexpr std::size_t n = 64;
  std::vector<double> exact(n, 0.0), shifted(n, 0.0);
  exact[20] = n, shifted[21] = n;  // unit mass on a unit domain, as cell averages
  EXPECT_DOUBLE_EQ(l1_distance(shifted, exact, L1Scale::absolute).relative, 2.0);
  EXPECT_DOUBLE_EQ(mass_distance(shifted, exact), 1.0 / n);
  EXPECT_EQ(mass_distance(exact, exact), 0.0);
}

// Spread over the cells around it, the same delta-shock costs the mean
// distance its mass moves: half of it one cell each way, 1/2 cell on average.
// On a ring a shift of the whole density costs that shift, whichever way round.
TEST(FieldDistance, MassDistanceIsTheMeanDistanceTheMassMoves) {
  constexpr std::size_t n = 100;
  std::vector<double> exact(n, 0.0), spread(n, 0.0);
  exact[50] = n;
  spread[49] = spread[51] = 0.25 * n, spread[50] = 0.5 * n;
  EXPECT_NEAR(mass_distance(spread, exact), 0.5 / n, 1e-15);
  std::vector<double> bumps(n), moved(n);
  for (std::size_t i = 0; i < n; ++i) bumps[i] = i % 10 == 0 ? 10.0 : 0.0;  // a delta-shock every 10 cells
  for (std::size_t i = 0; i < n; ++i) moved[(i + 3) % n] = bumps[i];  // each 3 cells on, 7 short of the next
  EXPECT_NEAR(mass_distance(moved, bumps), 3.0 / n, 1e-12);
  EXPECT_THROW(mass_distance({0, 0}, {1, 1}), InputError);
  EXPECT_THROW(mass_distance({1, 1, 1}, {1, 1}), InputError);
}

}  // namespace
}  // namespace shockgas::compare
