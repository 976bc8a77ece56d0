#pragma once
// Loads the memory of the domain that runs next into the second-level cache a
// few lines at a time, while other domains run (private to particles/): its
// bodies, slot times and tree nodes then arrive without a stall.
#include <algorithm>
#include <array>
#include <cstddef>

#include "shockgas/particles/window_domain.hpp"

namespace shockgas::particles::detail {

class DomainPrefetcher {
 public:
  // How many lines of the next domain to load per round of the streams: enough
  // to have it all in cache when it starts, for domains of `bodies` bodies of
  // `bytes` each (body and slot time) that take `steps` collisions each in the
  // sub-window (from the rate of the last one; speed only). Sub-windows that
  // hold few collisions per body (early times, dense samples) would otherwise
  // wait on one miss after another.
  static std::size_t lines_per_round(double bodies, double bytes, double steps) {
    if (!(steps > 0)) return 2;
    // Four times the even rate: the domain taken next has been claimed ahead for
    // only part of a domain's run (measured best at N = 10^7, t = 10: 3 to 6).
    return static_cast<std::size_t>(std::clamp(4.0 * bodies * bytes / 64.0 / steps, 2.0, 64.0));
  }

  // Loads domain d next (nothing if null): its bodies and slot times, of the
  // n of the chain (on a ring they may wrap past the end), and its tree's nodes.
  template <class Body>
  void aim(const Domain* d, const Body* body, const double* slot, std::size_t n) {
    clear();
    if (!d) return;
    auto add_bodies = [&](std::size_t lo, std::size_t hi) {  // bodies and slots lo .. hi - 1
      add(body + lo, body + hi);
      add(slot + lo, slot + hi);
    };
    if (d->head <= d->tail) {
      add_bodies(d->head, d->tail + 1);
    } else {
      add_bodies(d->head, n);
      add_bodies(0, d->tail + 1);
    }
    add(d->tree.node_keys(), d->tree.node_keys() + d->tree.node_count());
    add(d->tree.node_slots(), d->tree.node_slots() + d->tree.node_count());
  }

  void clear() { count_ = current_ = 0; }
  // Adds the bytes [begin, end) to load.
  void add(const void* begin, const void* end) {
    if (begin < end && count_ < ranges_.size())
      ranges_[count_++] = {static_cast<const char*>(begin), static_cast<const char*>(end)};
  }
  // Loads up to `lines` more cache lines, in the order added.
  void advance(std::size_t lines) {
    for (; lines > 0 && current_ < count_; --lines) {
      Range& r = ranges_[current_];
      prefetch_line_l2(r.next);
      r.next += 64;
      if (r.next >= r.end) ++current_;
    }
  }

 private:
  struct Range {
    const char *next, *end;
  };
  std::array<Range, 8> ranges_{};
  std::size_t count_ = 0, current_ = 0;
};

}  // namespace shockgas::particles::detail
