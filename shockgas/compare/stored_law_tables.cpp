// The white-noise laws' tables that depend on no scene: the zeros of Ai
// (airy_zeros, cluster_velocity_law.hpp), ln g on Chebyshev panels
// (chernoff_log_g_table, chernoff_table.hpp), the cluster velocity law's
// quadrature and CDF table (cluster_velocity_law) and its second moment
// (cluster_law_second_moment). Computing them costs about 0.23 s of a core.
//
// The build computes them once: generate_law_tables (generate/) runs the
// library's sources that compute them, compiled with the build's global
// options (those that decide floating-point results: -ffp-contract=off, the
// target's -march; not the library's position-independent code, which does
// not), and writes them as hexadecimal floating-point literals, which are
// exact, into law_tables.inc in the build tree; this file compiles them in,
// and the instance functions below hand them out. The numbers are those a run-time computation gives on the
// build machine, bit for bit (tests/compare/test_law_tables.cpp computes them
// afresh and compares): the C library's exp, log and sin may pick other code
// on another processor (glibc chooses by its features at start-up), so a
// package built elsewhere carries its build machine's last bits, as its other
// constants do.
#include <iterator>
#include <vector>

#include "shockgas/compare/chernoff_table.hpp"
#include "shockgas/compare/cluster_velocity_law.hpp"
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

}  // namespace shockgas::compare
