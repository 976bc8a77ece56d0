#pragma once
// The particles of a realization in chain order, a chunk at a time: what a model
// that keeps its own copy of the state (the event engine) reads instead of a
// whole Bodies copy. The same bodies, bit for bit, as make_initial_bodies.
//
//   InitialStream s = stream_realization(initial, k);
//   while (s.remaining() > 0) s.next(count, x, v, m);
//
// Drawn on the fly (lattice or random positions, uniform or Gaussian
// velocities): lattice positions need no storage; random positions keep their
// sorted positions (8 bytes per particle) until the last chunk is read; with
// remove_mean the velocities are drawn twice (a first pass sums the momentum).
// A stream of the velocities alone (Parts::velocities) skips the positions'
// draws without keeping or sorting them. Otherwise read from bodies held
// elsewhere (an InitialCondition's).
#include <cstddef>
#include <cstdint>
#include <vector>

#include "shockgas/core/initial_condition.hpp"
#include "shockgas/core/random.hpp"

namespace shockgas {

class InitialStream {
 public:
  // What next() writes: all of x, v, m, or v and m alone (x is then not to be
  // read; drawn bodies leave it unset, held ones fill it).
  enum class Parts { all, velocities };

  // True when p's particles can be drawn on the fly: lattice or random
  // positions with uniform or Gaussian velocities (not a file, not an expression).
  static bool streamable(const InitialParams& p);

  // Realization `realization` drawn on the fly; p must be streamable and valid.
  InitialStream(const InitialParams& p, std::uint64_t realization, Parts parts = Parts::all);
  // The bodies of `held`, which must outlive the stream.
  explicit InitialStream(const Bodies& held);

  std::size_t size() const { return n_; }
  // The mean mass M / N of its bodies: 1 when drawn (unit masses), else the held bodies'.
  double mean_mass() const;
  std::size_t remaining() const { return n_ - next_; }
  // Writes the next count <= remaining() bodies: x ascending (unless the
  // stream has Parts::velocities), v, m.
  void next(std::size_t count, double* x, double* v, double* m);

 private:
  double draw_velocity(Rng& rng) const;

  const Bodies* held_ = nullptr;
  std::size_t n_ = 0, next_ = 0;
  double length_ = 0, amplitude_ = 1, mean_ = 0;
  bool lattice_ = true, gaussian_ = false, positions_wanted_ = true;
  Rng rng_{0};                     // positioned at the next body's velocity
  std::vector<double> positions_;  // random positions, sorted; empty on a lattice
};

// Reads the rest of `stream` through a buffer of `chunk` bodies: f(x, v, m, count)
// for each chunk, in order (x unset on a stream of the velocities alone).
template <class F>
void read_in_chunks(InitialStream& stream, F&& f, std::size_t chunk = 4096) {
  std::vector<double> x(chunk), v(chunk), m(chunk);
  while (stream.remaining() > 0) {
    const std::size_t count = stream.remaining() < chunk ? stream.remaining() : chunk;
    stream.next(count, x.data(), v.data(), m.data());
    f(x.data(), v.data(), m.data(), count);
  }
}

// Mass-weighted temperature <v^2> - <v>^2 of realization k, as a run of it
// finds it (RunResult::initial_temperature), bit for bit: TemperatureSums over
// its bodies in order, held or drawn in chunks, without a whole copy (equal to
// temperature(make_initial_bodies(...)) to rounding).
double initial_temperature(const InitialCondition& initial, std::uint64_t k);

// Realization k of `initial` a chunk at a time without a whole copy: read from
// initial.bodies() where it holds them and they are realization k (k = 0, or
// data that do not depend on k), else drawn on the fly.
InitialStream stream_realization(const InitialCondition& initial, std::uint64_t k,
                                 InitialStream::Parts parts = InitialStream::Parts::all);

}  // namespace shockgas
