// generate_law_tables OUT: computes the white-noise laws' tables
// (stored_law_tables.cpp) and writes them to OUT as C++ constants with hexadecimal
// floating-point literals (printf's %a: exact), for stored_law_tables.cpp.
// Here the instance functions compute: airy_zeros by airy_ai_zero, the table
// and the law by their computing constructors, the moment by quadrature
// (shockgas/compare/CMakeLists.txt lists the sources this links).
#include <cstdio>
#include <exception>
#include <stdexcept>
#include <string>
#include <vector>

#include "shockgas/compare/chernoff_table.hpp"
#include "shockgas/compare/cluster_velocity_law.hpp"

namespace shockgas::compare {

const std::vector<double>& airy_zeros() {
  static const std::vector<double> zeros = compute_airy_zeros();
  return zeros;
}

const ChernoffLogGTable& chernoff_log_g_table() {
  static const ChernoffLogGTable table;
  return table;
}

const ClusterVelocityLaw& cluster_velocity_law() {
  static const ClusterVelocityLaw law;
  return law;
}

double cluster_law_second_moment() { return compute_cluster_law_second_moment(cluster_velocity_law()); }

}  // namespace shockgas::compare

namespace {

void write_number(std::FILE* out, const char* name, double value) {
  std::fprintf(out, "constexpr double %s = %a;\n", name, value);
}

void write_array(std::FILE* out, const char* name, const std::vector<double>& values) {
  std::fprintf(out, "constexpr double %s[%zu] = {\n", name, values.size());
  for (std::size_t k = 0; k < values.size(); ++k)
    std::fprintf(out, "%a,%s", values[k], (k + 1) % 4 == 0 || k + 1 == values.size() ? "\n" : " ");
  std::fprintf(out, "};\n");
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: generate_law_tables OUT\n");
    return 2;
  }
  try {
    namespace c = shockgas::compare;
    const std::string path = argv[1], partial = path + ".part";
    std::FILE* out = std::fopen(partial.c_str(), "w");
    if (!out) throw std::runtime_error("cannot write " + partial);
    std::fprintf(
        out, "// Written by generate_law_tables (shockgas/compare/stored_law_tables.cpp): do not edit.\n");
    std::fprintf(out, "#pragma once\n\nnamespace shockgas::compare::stored {\n\n");
    write_array(out, "kAiryZeros", c::airy_zeros());
    const c::ChernoffLogGTable& g = c::chernoff_log_g_table();
    write_number(out, "kChernoffLo", g.lo());
    write_number(out, "kChernoffHi", g.hi());
    write_array(out, "kChernoffCoefficients", g.coefficients());
    const c::ClusterVelocityLaw::Nodes& law = c::cluster_velocity_law().nodes();
    write_array(out, "kClusterLawMu", law.mu);
    write_array(out, "kClusterLawWeight", law.weight);
    write_array(out, "kClusterLawCumulative", law.cumulative);
    write_number(out, "kClusterLawShocks", law.shocks);
    write_number(out, "kClusterLawSecondMoment", c::cluster_law_second_moment());
    std::fprintf(out, "\n}  // namespace shockgas::compare::stored\n");
    // A write that failed midway (a full disk) leaves the stream's error set
    // even where the last flush succeeds: the file is not moved into place.
    const bool written = std::ferror(out) == 0;
    if (std::fclose(out) != 0 || !written || std::rename(partial.c_str(), path.c_str()) != 0) {
      std::remove(partial.c_str());
      throw std::runtime_error("cannot write " + path);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "generate_law_tables: %s\n", e.what());
    return 1;
  }
  return 0;
}
