#pragma once
// An event engine loaded from bodies of unit mass (the engine's streamed
// loading, fed from a Bodies copy), for the engine and window tests.
#include <algorithm>
#include <cstddef>

#include "shockgas/core/bodies.hpp"
#include "shockgas/particles/event_engine.hpp"

namespace shockgas::particles::detail {

// Bodies b (sorted by x, inside [0, N) on a ring) of unit mass on a ring or a
// line of length N = b.size().
template <bool Linked>
EventEngine<Linked> engine_of(const Bodies& b, bool ring, const CollisionRule& rule) {
  return EventEngine<Linked>(b.size(), static_cast<double>(b.size()), ring, rule,
                             [&](std::size_t first, std::size_t count, double* x, double* v, double* m) {
                               std::copy_n(b.x.begin() + first, count, x);
                               std::copy_n(b.v.begin() + first, count, v);
                               std::fill_n(m, count, 1.0);
                             });
}

}  // namespace shockgas::particles::detail
