// The white-noise laws' tables the build stored (stored_law_tables.cpp) against the
// same tables computed here, bit for bit: the stored ones are what a run-time
// computation gives, as the laws' own tests (test_cluster_velocity_law.cpp,
// test_shock_mass_law.cpp) assume.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <vector>

#include "shockgas/compare/chernoff.hpp"
#include "shockgas/compare/chernoff_table.hpp"
#include "shockgas/compare/cluster_velocity_law.hpp"

namespace shockgas::compare {
namespace {

std::vector<std::uint64_t> bits(const std::vector<double>& values) {
  std::vector<std::uint64_t> b;
  for (const double v : values) b.push_back(std::bit_cast<std::uint64_t>(v));
  return b;
}

std::uint64_t bits(double value) { return std::bit_cast<std::uint64_t>(value); }

// The instance functions hand out the stored tables; here they are computed.
TEST(LawTables, TheStoredTablesAreTheComputedOnesBitForBit) {
  EXPECT_EQ(bits(airy_zeros()), bits(compute_airy_zeros()));
  const ChernoffLogGTable& stored_table = chernoff_log_g_table();
  const ChernoffLogGTable table;  // computed, on the default range
  EXPECT_EQ(bits(stored_table.lo()), bits(table.lo()));
  EXPECT_EQ(bits(stored_table.hi()), bits(table.hi()));
  EXPECT_EQ(bits(stored_table.coefficients()), bits(table.coefficients()));
  // The law's computation reads the table and the zeros, held equal above.
  const ClusterVelocityLaw::Nodes& stored = cluster_velocity_law().nodes();
  const ClusterVelocityLaw law;
  EXPECT_EQ(bits(stored.mu), bits(law.nodes().mu));
  EXPECT_EQ(bits(stored.weight), bits(law.nodes().weight));
  EXPECT_EQ(bits(stored.cumulative), bits(law.nodes().cumulative));
  EXPECT_EQ(bits(stored.shocks), bits(law.nodes().shocks));
  EXPECT_EQ(bits(cluster_law_second_moment()), bits(compute_cluster_law_second_moment(law)));
}

// Why the table reaches 12 (chernoff_table.hpp): the convolutions' terms
// exp(ln g(a) + ln g(b)) with a in (11, 12] are 0.0 whichever way ln g(a) is
// evaluated, as ln g(a) < -880 there and ln g <= 1 everywhere (exp underflows
// to 0 below -745.2).
TEST(LawTables, PastElevenATermOfTheConvolutionsIsZeroEitherWay) {
  const ChernoffLogGTable& table = chernoff_log_g_table();
  double largest = -INFINITY;
  for (double x = -11.0; x <= 12.0; x += 0.01) largest = std::max(largest, table.log_g(x));
  EXPECT_LT(largest, 1.0);
  for (double x = 11.0 + 1e-9; x <= 12.0; x += 0.0731) {
    EXPECT_LT(chernoff_log_g(x), -880.0) << x;
    EXPECT_LT(table.log_g(x), -880.0) << x;
    EXPECT_EQ(std::exp(chernoff_log_g(x) + largest), 0.0) << x;
    EXPECT_EQ(std::exp(table.log_g(x) + largest), 0.0) << x;
  }
}

}  // namespace
}  // namespace shockgas::compare
