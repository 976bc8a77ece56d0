#pragma once
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
// exact; stored_law_tables.cpp compiles them in, and the instance functions
// hand them out. The numbers are those a run-time computation gives on the
// build machine, bit for bit (tests/compare/test_law_tables.cpp computes them
// afresh and compares): the C library's exp, log and sin may pick other code
// on another processor (glibc chooses by its features at start-up), so a
// package built elsewhere carries its build machine's last bits, as its other
// constants do.
#include <vector>

#include "shockgas/compare/cluster_velocity_law.hpp"

namespace shockgas::compare {

struct LawTables {
  std::vector<double> airy_zeros;             // a_1 .. a_1000
  double chernoff_lo = 0, chernoff_hi = 0;    // ChernoffLogGTable's range
  std::vector<double> chernoff_coefficients;  // ... and coefficients
  ClusterVelocityLaw::Nodes cluster_law;
  double second_moment = 0;  // E_mass u^2
};

// The tables as the instance functions hold them (what the test compares).
LawTables stored_law_tables();

}  // namespace shockgas::compare
