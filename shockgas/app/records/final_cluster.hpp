#pragma once
// Realization 0's heaviest cluster at its end (summary: analysis.heaviest_cluster_*),
// found by the comparison's cluster criteria (compare::snapshot_params: the gas's
// default criteria at the end time, or compare.cluster_gap / cluster_dv) as the
// final state goes by, whether or not the state itself is kept.
#include <optional>

#include "shockgas/app/scene/scene.hpp"
#include "shockgas/particles/state_sink.hpp"

namespace shockgas::app {

// Centre of mass [length], velocity (momentum / mass) [length/time] and mass [mass].
struct HeaviestCluster {
  double x = 0, v = 0, m = 0;
};

// The heaviest cluster of a final state of `scene` reached at time t, its
// initial condition of length `length` (the ring's, or the line's extent);
// none for an empty state.
std::optional<HeaviestCluster> heaviest_final_cluster(const Scene& scene, double length, double t,
                                                      const particles::StateReader& state);

}  // namespace shockgas::app
