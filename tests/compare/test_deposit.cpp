#include <gtest/gtest.h>

#include <numeric>

#include "shockgas/compare/deposit.hpp"
#include "shockgas/core/error.hpp"
#include "shockgas/core/random.hpp"

namespace shockgas::compare {
namespace {

double sum(const std::vector<double>& v) { return std::accumulate(v.begin(), v.end(), 0.0); }

TEST(Deposit, NearestCellPutsEachBodyInItsCell) {
  Bodies b;
  b.push_back(0.05, 1.0, 2.0);
  b.push_back(0.07, 4.0, 1.0);
  b.push_back(0.75, -1.0, 1.0);
  const GridFields g = deposit_on_grid(b, 1.0, 10, DepositScheme::nearest_cell);
  ASSERT_EQ(g.x.size(), 10u);
  EXPECT_DOUBLE_EQ(g.mass[0], 3.0);
  EXPECT_DOUBLE_EQ(g.rho[0], 30.0);
  EXPECT_DOUBLE_EQ(g.v[0], 2.0);  // (2 * 1 + 1 * 4) / 3
  EXPECT_DOUBLE_EQ(g.mass[7], 1.0);
  EXPECT_DOUBLE_EQ(g.v[7], -1.0);
  // Empty cells 1..6 interpolate linearly from v = 2 (cell 0) to v = -1 (cell 7).
  EXPECT_DOUBLE_EQ(g.mass[3], 0.0);
  EXPECT_NEAR(g.v[3], 2.0 - 3.0 * 3.0 / 7.0, 1e-14);  // a few ulps of O(1)
  // ... and periodically from cell 7 back to cell 0 across x = 0.
  EXPECT_NEAR(g.v[9], -1.0 + 3.0 * 2.0 / 3.0, 1e-14);
}

TEST(Deposit, CloudInCellSplitsBetweenNeighbouringCentres) {
  Bodies b;
  b.push_back(0.35, 1.0, 1.0);   // on the centre of cell 3: all of it there
  b.push_back(0.70, 2.0, 1.0);   // midway between centres 0.65 and 0.75
  b.push_back(0.99, -1.0, 1.0);  // past the last centre 0.95: 60% to cell 9, 40% to cell 0
  const GridFields g = deposit_on_grid(b, 1.0, 10, DepositScheme::cloud_in_cell);
  // Offsets are of O(1) numbers: rounding of a few ulps.
  EXPECT_NEAR(g.mass[3], 1.0, 1e-14);
  EXPECT_NEAR(g.mass[6], 0.5, 1e-14);
  EXPECT_NEAR(g.mass[7], 0.5, 1e-14);
  EXPECT_NEAR(g.mass[9], 0.6, 1e-14);
  EXPECT_NEAR(g.mass[0], 0.4, 1e-14);
  EXPECT_NEAR(g.v[6], 2.0, 1e-14);
}

TEST(Deposit, BothSchemesConserveMassAndMomentum) {
  Rng rng(5);
  Bodies b;
  for (int i = 0; i < 1000; ++i) b.push_back(100.0 * i / 1000 + 0.05 * rng.uniform(), rng.uniform(-1, 1), 1);
  for (DepositScheme s : {DepositScheme::nearest_cell, DepositScheme::cloud_in_cell}) {
    const GridFields g = deposit_on_grid(b, 100.0, 64, s);
    // Sums of 1000 O(1) terms: rounding ~ 1e-13.
    EXPECT_NEAR(sum(g.mass), total_mass(b), 1e-10);
    EXPECT_NEAR(sum(g.momentum), total_momentum(b), 1e-10);
  }
}

TEST(Deposit, ParsesSchemesAndRejectsBadInput) {
  EXPECT_EQ(parse_deposit_scheme("cic", "k"), DepositScheme::cloud_in_cell);
  EXPECT_EQ(parse_deposit_scheme("nearest", "k"), DepositScheme::nearest_cell);
  EXPECT_THROW(parse_deposit_scheme("spline", "k"), InputError);
  EXPECT_THROW(deposit_on_grid(Bodies{}, 0.0, 10, DepositScheme::cloud_in_cell), InputError);
  EXPECT_THROW(deposit_on_grid(Bodies{}, 1.0, 0, DepositScheme::cloud_in_cell), InputError);
}

}  // namespace
}  // namespace shockgas::compare
