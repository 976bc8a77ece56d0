#pragma once
// Loads the memory of the domain that runs next into the second-level cache a
// few lines at a time, while other domains run (private to particles/): its
// bodies, slot times and tree nodes then arrive without a stall.
#include <array>
#include <cstddef>

#include "event_tree.hpp"

namespace shockgas::particles::detail {

class DomainPrefetcher {
 public:
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
