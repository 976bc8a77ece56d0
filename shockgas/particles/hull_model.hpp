#pragma once
// The exact sticky gas as a model (particles.solver = hull, r = 0): the
// observables of RunResult from the lower-convex-hull solution at each stop
// time (shockgas/core/sticky_hull.hpp), without simulating events: built from the bodies
// at the first stop, then advanced from its own clusters (they only merge), one
// pass over the clusters per stop. Private to particles/.
#include "shockgas/core/bodies.hpp"
#include "shockgas/core/initial_stream.hpp"
#include "shockgas/particles/params.hpp"
#include "shockgas/particles/run_result.hpp"
#include "shockgas/particles/state_sink.hpp"

namespace shockgas::particles::detail {

// Collisions are merges: N - (number of clusters); dissipated energy: the
// kinetic energy lost since t = 0. Inputs checked by the caller. With a sink,
// the snapshots and the final state go to it. Interruption is polled between
// stops: each stop is a safe point.
RunResult simulate_hull(const Bodies& initial, double L, bool ring, const ParticleParams& p,
                        const StateSink* sink = nullptr);
// The same from bodies of one mass drawn in chunks, never held whole (the
// hull keeps its clusters only: 20 bytes each).
RunResult simulate_hull(InitialStream& initial, double L, bool ring, const ParticleParams& p,
                        const StateSink* sink = nullptr);

}  // namespace shockgas::particles::detail
