#pragma once
// Reads the comma-separated reference tables of tests/compare/data/ (made by
// scripts/reference/chernoff_reference.py): one row of numbers per line, '#' comments.
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace shockgas::compare::testing {

inline std::vector<std::vector<double>> read_reference_table(const std::string& name) {
  const std::string path = std::string(SHOCKGAS_SOURCE_DIR) + "/tests/compare/data/" + name;
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::vector<std::vector<double>> rows;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    std::vector<double> row;
    for (std::string field; std::getline(fields, field, ',');) row.push_back(std::stod(field));
    rows.push_back(row);
  }
  return rows;
}

}  // namespace shockgas::compare::testing
