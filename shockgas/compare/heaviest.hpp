#pragma once
// Where the mass gathers: the heaviest shock of a continuum field and the
// heaviest cluster of a particle state, the two things to point at when a
// delta-shock forms. With a uniform initial density the sticky gas and Burgers'
// equation share their shocks, so the two coincide; with a non-uniform one they
// part: a Burgers shock moves at (v_L + v_R) / 2 whatever the densities, a
// sticky cluster (the pressureless gas's delta-shock) at its momentum / mass
// (docs/design.md §2, rung 2).
#include <optional>

#include "shockgas/continuum/field.hpp"
#include "shockgas/core/bodies.hpp"
#include "shockgas/particles/cluster_finder.hpp"

namespace shockgas::compare {

// The shock holding the most mass: from the solver's own list, else from the
// shocks found in its fields (shock_detection.hpp; a shock's mass is the excess
// over the background density). None if no shock holds mass (no shock, or a
// field without density).
std::optional<continuum::Shock> heaviest_shock(const continuum::ContinuumResult& field);

// The heaviest cluster of a state (find_clusters with these criteria; ring
// length L, 0 on a line). None for an empty state.
std::optional<particles::Cluster> heaviest_cluster(const Bodies& state, double L,
                                                   const particles::ClusterCriteria& criteria);
// The same from a state read in chunks (particles::visit_clusters), never held whole.
std::optional<particles::Cluster> heaviest_cluster(const particles::StateReader& state, double L,
                                                   const particles::ClusterCriteria& criteria);

}  // namespace shockgas::compare
