#pragma once
// Progress reporting from long computations to whoever runs them. Engines call
// it now and then (not per event); the command draws the bar.
#include <cstdint>
#include <functional>

namespace shockgas {

// fraction: in [0, 1] of the work; sim_time: the simulated time reached;
// events: the events (collisions) done so far, for a rate, or 0 where the
// computation does not count them (the continuum solvers).
using ProgressCallback = std::function<void(double fraction, double sim_time, std::uint64_t events)>;

}  // namespace shockgas
