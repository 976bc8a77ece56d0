#pragma once
// The predicted event times of the pair slots (private to particles/), in blocks
// of 16 (two cache lines, one 128-byte unit), and the cache hints the engine uses
// on them.
#include <algorithm>
#include <cstddef>
#include <limits>
#include <vector>

#include "shockgas/particles/huge_page_allocator.hpp"

namespace shockgas::particles {

// Starts loading the cache line at p (any address; it is never dereferenced).
// Inline assembly, because GCC 12 at -O2 finds a function whose only effect is
// __builtin_prefetch "pure" and deletes the calls to it.
inline void prefetch_line(const void* p) {
#if defined(__x86_64__) || defined(__i386__)
  asm volatile("prefetcht0 (%0)" : : "r"(p));
#else
  __builtin_prefetch(p, 1);
#endif
}
// The same into the second-level cache only: for data needed in a while, which
// should not push the data in use out of the first level.
inline void prefetch_line_l2(const void* p) {
#if defined(__x86_64__) || defined(__i386__)
  asm volatile("prefetcht1 (%0)" : : "r"(p));
#else
  __builtin_prefetch(p, 1, 2);
#endif
}

// The event times of n pair slots, in blocks of 16 (the event tree's leaves:
// two cache lines that the second-level cache fetches as a pair); the padding
// after slot n - 1 stays at +inf.
class SlotTimes {
 public:
  static constexpr double never = std::numeric_limits<double>::infinity();
  static constexpr std::size_t block = 16;  // slot times per block (two cache lines)

  // n slots, all at +inf (each block written once).
  void reset(std::size_t n) {
    n_ = n;
    Block unset;
    std::fill(unset.t, unset.t + block, never);
    blocks_.assign((n + block - 1) / block, unset);
  }
  std::size_t size() const { return n_; }
  std::size_t blocks() const { return blocks_.size(); }
  double& operator[](std::size_t i) { return blocks_[i / block].t[i % block]; }
  double operator[](std::size_t i) const { return blocks_[i / block].t[i % block]; }
  const double* block_data(std::size_t b) const { return blocks_[b].t; }
  double* data() { return blocks_.empty() ? nullptr : blocks_[0].t; }

 private:
  struct alignas(128) Block {
    double t[block];
  };
  std::vector<Block, HugePageAllocator<Block>> blocks_;
  std::size_t n_ = 0;
};

}  // namespace shockgas::particles
