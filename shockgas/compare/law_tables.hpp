#pragma once
// The white-noise laws' tables that depend on no scene: the zeros of Ai
// (airy_zeros, cluster_velocity_law.hpp), ln g on Chebyshev panels
// (chernoff_log_g_table, chernoff_table.hpp), the cluster velocity law's
// quadrature and CDF table (cluster_velocity_law) and its second moment
// (cluster_law_second_moment). Computing them costs about 0.35 s of a core,
// which every run from white noise on a lattice paid before its analysis.
//
// The build computes them once: generate_law_tables (generate/) runs the code
// that computes them, compiled with this build's options, and writes them as
// hexadecimal floating-point literals, which are exact; stored_law_tables.cpp
// compiles them in, and the instance functions hand them out. A run reads the
// same numbers a run-time computation would give, bit for bit
// (tests/compare/test_law_tables.cpp computes them afresh and compares).
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

// The tables as the instance functions hold them.
LawTables stored_law_tables();

}  // namespace shockgas::compare
