#pragma once
// Where the states a run writes (snapshots, the final state) go as they are
// reached, in chunks, instead of as whole copies in RunResult: a file writer
// streams them (simulate.hpp).
#include <cstddef>
#include <functional>

namespace shockgas::particles {

// A state to be written, handed out in chunks instead of as a whole copy:
// sorted by x (ring: x in [0, L)), each body once, as RunResult::final_state
// would hold it. read() may be called more than once.
class StateReader {
 public:
  using Chunk = std::function<void(const double* x, const double* v, const double* m, std::size_t count)>;
  virtual std::size_t size() const = 0;  // bodies
  virtual void read(const Chunk& chunk) const = 0;

 protected:
  ~StateReader() = default;
};

// The receiver of a run's states; RunResult's final_state and snapshots then
// stay empty. Snapshot k is at the k-th of params.snapshots in ascending order.
// A member left empty discards that state.
struct StateSink {
  std::function<void(std::size_t k, double t, const StateReader& state)> snapshot;
  std::function<void(double t, const StateReader& state)> final_state;
};

}  // namespace shockgas::particles
