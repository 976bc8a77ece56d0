// The instances of the white-noise laws' tables, from the build's computation
// (law_tables.hpp): law_tables.inc, written by generate_law_tables.
#include <iterator>

#include "shockgas/compare/chernoff_table.hpp"
#include "shockgas/compare/cluster_velocity_law.hpp"
#include "shockgas/compare/law_tables.hpp"
#include "shockgas/compare/law_tables.inc"

namespace shockgas::compare {

namespace {

template <std::size_t N>
std::vector<double> vector_of(const double (&values)[N]) {
  return std::vector<double>(std::begin(values), std::end(values));
}

}  // namespace

const std::vector<double>& airy_zeros() {
  static const std::vector<double> zeros = vector_of(stored::kAiryZeros);
  return zeros;
}

const ChernoffLogGTable& chernoff_log_g_table() {
  static const ChernoffLogGTable table(stored::kChernoffLo, stored::kChernoffHi,
                                       vector_of(stored::kChernoffCoefficients));
  return table;
}

const ClusterVelocityLaw& cluster_velocity_law() {
  static const ClusterVelocityLaw law({vector_of(stored::kClusterLawMu), vector_of(stored::kClusterLawWeight),
                                       vector_of(stored::kClusterLawCumulative), stored::kClusterLawShocks});
  return law;
}

double cluster_law_second_moment() { return stored::kClusterLawSecondMoment; }

LawTables stored_law_tables() {
  const ChernoffLogGTable& g = chernoff_log_g_table();
  return {airy_zeros(),
          g.lo(),
          g.hi(),
          g.coefficients(),
          cluster_velocity_law().nodes(),
          cluster_law_second_moment()};
}

}  // namespace shockgas::compare
