#pragma once
// Scene table [compare]: the particle analysis (cooling law, velocity
// distribution) and the particle-continuum comparison at one time.
#include <string>

#include "shockgas/compare/deposit.hpp"
#include "shockgas/continuum/registry.hpp"
#include "shockgas/core/parameters.hpp"

namespace shockgas::compare {

// Unit, allowed range and meaning of every member: parameters() (shockgas/compare/params.cpp).
struct CompareParams {
  std::string solver = continuum::reference_solver_name();  // one of continuum.solvers
  DepositScheme deposit = DepositScheme::cloud_in_cell;
  double distribution_t_min = 10.0;
  double match_distance = 0.0;       // 0 = automatic
  double min_cluster_particles = 0;  // 0 = automatic (theory.hpp)
  double cluster_gap = 0.0;          // 0 = derived from delta
  double cluster_dv = 0.0;           // 0 = derived from delta
  double fit_window = 10.0;
};

// The declarations of [compare]: key, unit, allowed values, doc.
const ParameterTable<CompareParams>& parameters();

// Throws InputError naming the first key out of range.
void validate(const CompareParams& p);

}  // namespace shockgas::compare
