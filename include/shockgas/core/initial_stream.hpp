#pragma once
// The particles of a realization in chain order, a chunk at a time: what a model
// that keeps its own copy of the state (the event engine) reads instead of a
// whole Bodies copy. The same bodies, bit for bit, as make_initial_bodies.
//
//   InitialStream s(params, k);
//   while (s.remaining() > 0) s.next(count, x, v, m);
//
// Lattice positions need no storage; random positions keep their sorted
// positions (8 bytes per particle) until the last chunk is read. With
// remove_mean the velocities are drawn twice (a first pass sums the momentum).
#include <cstddef>
#include <cstdint>
#include <vector>

#include "shockgas/core/initial_condition.hpp"
#include "shockgas/core/random.hpp"

namespace shockgas {

class InitialStream {
 public:
  // True when p's particles can be streamed: lattice or random positions with
  // uniform or Gaussian velocities (not a file, not an expression).
  static bool streamable(const InitialParams& p);

  // p must be streamable and valid.
  InitialStream(const InitialParams& p, std::uint64_t realization);

  std::size_t size() const { return n_; }
  std::size_t remaining() const { return n_ - next_; }
  // Writes the next count <= remaining() bodies: x ascending in [0, L), v, m = 1.
  void next(std::size_t count, double* x, double* v, double* m);

 private:
  double draw_velocity(Rng& rng) const;

  std::size_t n_ = 0, next_ = 0;
  double length_ = 0, amplitude_ = 1, mean_ = 0;
  bool lattice_ = true, gaussian_ = false;
  Rng rng_;                        // positioned at the next body's velocity
  std::vector<double> positions_;  // random positions, sorted; empty on a lattice
};

}  // namespace shockgas
