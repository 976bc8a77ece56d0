#pragma once
// Where the states a run writes (snapshots, the final state) go as they are
// reached, in chunks, instead of as whole copies in RunResult: a file writer
// streams them (simulate.hpp).
#include <algorithm>
#include <array>
#include <cstddef>
#include <functional>
#include <optional>

#include "shockgas/core/bodies.hpp"

namespace shockgas::particles {

// A state to be written, handed out in chunks instead of as a whole copy:
// sorted by x (ring: x in [0, L)), each body once, as RunResult::final_state
// would hold it. read() may be called more than once.
class StateReader {
 public:
  using Chunk = std::function<void(const double* x, const double* v, const double* m, std::size_t count)>;
  virtual std::size_t size() const = 0;  // bodies
  virtual void read(const Chunk& chunk) const = 0;
  // The last body read() hands out, {x, v, m}, where the reader knows it
  // without a read; else nullopt (then a walk that needs it reads twice).
  virtual std::optional<std::array<double, 3>> last() const { return std::nullopt; }

 protected:
  ~StateReader() = default;
};

// Bodies held whole, read as a state: chunks of up to 4096 bodies in place.
class BodiesReader final : public StateReader {
 public:
  explicit BodiesReader(const Bodies& bodies) : b_(bodies) {}
  std::size_t size() const override { return b_.size(); }
  void read(const Chunk& chunk) const override {
    for (std::size_t i = 0; i < b_.size(); i += 4096)
      chunk(b_.x.data() + i, b_.v.data() + i, b_.m.data() + i, std::min<std::size_t>(4096, b_.size() - i));
  }
  std::optional<std::array<double, 3>> last() const override {
    if (b_.size() == 0) return std::nullopt;
    return std::array<double, 3>{b_.x.back(), b_.v.back(), b_.m.back()};
  }

 private:
  const Bodies& b_;
};

// The receiver of a run's states; RunResult's final_state and snapshots then
// stay empty. Snapshot k is at the k-th of params.snapshots in ascending order.
// A member left empty discards that state.
struct StateSink {
  std::function<void(std::size_t k, double t, const StateReader& state)> snapshot;
  std::function<void(double t, const StateReader& state)> final_state;
};

}  // namespace shockgas::particles
