#pragma once
// Progress reporting from long computations to whoever runs them. Engines call
// it now and then (not per event); the command draws the bar.
#include <functional>

namespace shockgas {

// fraction: in [0, 1] of the work; sim_time: the simulated time reached.
using ProgressCallback = std::function<void(double fraction, double sim_time)>;

}  // namespace shockgas
