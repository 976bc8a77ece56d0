#pragma once
// Event queue of the particle engine: a tournament (winner) tree over the pair
// slots.
//
// Contract:
//  * There are n slots (pair i = body i and its right neighbour); each holds one
//    predicted event time, +inf for "no event".
//  * set(i, t) replaces slot i's time; the tree is consistent only after the
//    matching refresh (refresh_path(i), or refresh_range(lo, hi) covering every slot
//    set since the last refresh).
//  * top() is a slot with the smallest time, O(1).
//
// Layout. The slot times are stored in blocks of 8 (one cache line); the tree is
// over the blocks: the implicit heap of the bottom-up segment tree, leaves at
// nb..2nb-1 (nb blocks), node k < nb the winner of nodes 2k and 2k+1, so node 1 is
// the global winner for any nb (no padding to a power of two). A node stores the
// winner's time and slot (16 bytes), so a comparison never leaves the path being
// refreshed. A collision changes at most three adjacent slots, nearly always in
// one block: one line of times, then one path to the root. The tree is 4 bytes
// per slot (8 for the times), so at N = 10^6 its upper levels stay in cache.
#include <algorithm>
#include <cassert>
#include <cstddef>
#include <cstdint>
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

class EventTree {
 public:
  static constexpr double never = std::numeric_limits<double>::infinity();
  static constexpr std::size_t block = 8;  // slot times per cache line

  EventTree() = default;
  explicit EventTree(std::size_t n) { reset(n); }
  EventTree(const EventTree&) = delete;  // node_ and time_ point into owned lines
  EventTree& operator=(const EventTree&) = delete;

  // n slots, all at +inf.
  void reset(std::size_t n) {
    assert(n >= 1 && n < (std::size_t{1} << 31));
    n_ = n;
    nb_ = (n + block - 1) / block;
    hinting_ = n >= hint_slots;
    hint_ = 0;
    time_lines_.assign(nb_, TimeLine{});
    time_ = &time_lines_[0].t[0];
    for (std::size_t i = 0; i < nb_ * block; ++i) time_[i] = never;
    node_lines_.assign((2 * nb_ + 3) / 4, NodeLine{});
    node_ = &node_lines_[0].node[0];
    rebuild();
  }
  // Recomputes every block and internal node, O(n): after many set() calls.
  void rebuild() {
    for (std::size_t b = 0; b < nb_; ++b) node_[nb_ + b] = block_winner(b);
    for (std::size_t k = nb_ - 1; k >= 1; --k) pull(k);
  }

  std::size_t size() const { return n_; }
  double time(std::size_t slot) const { return time_[slot]; }
  std::size_t top() const { return node_[1].slot; }
  double top_time() const { return node_[1].t; }

  void set(std::size_t slot, double t) { time_[slot] = t; }
  // With hinting() (trees of hint_slots slots or more, too large for the caches):
  // a slot likely to hold the second-earliest time after the last refresh (see
  // climb), for prefetching only, never relied on. Otherwise 0.
  static constexpr std::size_t hint_slots = std::size_t{1} << 18;
  bool hinting() const { return hinting_; }
  std::size_t hint() const { return hint_; }

  // Refreshes the path of one slot.
  void refresh_path(std::size_t slot) { refresh_blocks(slot / block, slot / block); }
  // Refreshes slots lo..hi (hi - lo small).
  void refresh_range(std::size_t lo, std::size_t hi) {
    assert(lo <= hi && hi < n_);
    refresh_blocks(lo / block, hi / block);
  }
  // Hints the cache about a slot's block and the deep part of its path.
  void prefetch_path(std::size_t slot) const {
    prefetch_line(time_ + slot);
    for (std::size_t k = nb_ + slot / block; k >= 4096; k >>= 1) prefetch_line(node_ + k);
  }

 private:
  struct Node {
    double t;            // winner's event time
    std::uint32_t slot;  // winner's slot
    std::uint32_t pad;
  };
  struct alignas(64) NodeLine {
    Node node[4];
  };
  struct alignas(64) TimeLine {
    double t[block];
  };

  // The earliest slot of block b (branch-free scan of one cache line).
  Node block_winner(std::size_t b) const {
    const double* t = time_ + b * block;
    double best = t[0];
    std::uint32_t at = 0;
    for (std::uint32_t j = 1; j < block; ++j) {
      const bool take = t[j] < best;
      best = take ? t[j] : best;
      at ^= (at ^ j) & (0u - static_cast<std::uint32_t>(take));
    }
    return Node{best, static_cast<std::uint32_t>(b * block) + at, 0};
  }

  // Blocks a..b (b - a <= 1 in use) and their common path to the root.
  void refresh_blocks(std::size_t a, std::size_t b) {
    std::size_t ka = nb_ + a, kb = nb_ + b;
    for (std::size_t k = ka; k <= kb; ++k) node_[k] = block_winner(k - nb_);
    while (ka != kb) {  // leaves may sit at two depths: ka can reach the root first
      ka = ka > 1 ? ka >> 1 : 1;
      kb >>= 1;
      for (std::size_t k = kb; k >= ka; --k) pull(k);
    }
    climb(ka);
  }

  // Refreshes the ancestors of node k (k itself up to date). The winner so far
  // stays in registers; only the siblings are loaded, and their addresses do not
  // depend on the comparisons, so the loads overlap.
  //
  // On the way it keeps the runner-up among node k and the siblings (the winners
  // of the subtrees that partition the rest of the tree): the slot of the event
  // after the next one whenever that lies outside the next one's subtree (for
  // random positions, with probability 1 - sum_j 4^-j = 2/3). hint() serves it
  // for prefetching.
  void climb(std::size_t k) { hinting_ ? climb<true>(k) : climb<false>(k); }
  template <bool Hint>
  void climb(std::size_t k) {
    double t = node_[k].t;
    std::uint32_t slot = node_[k].slot;
    double t2 = never;
    std::uint32_t slot2 = slot;
    for (; k > 1; k >>= 1) {
      const Node& sib = node_[k ^ 1];
      // Selects by min/max and masks: no branch to mispredict.
      const bool take = sib.t < t;  // ties: either is a valid winner
      const std::uint32_t mask = 0u - static_cast<std::uint32_t>(take);
      if constexpr (Hint) {
        const double lose_t = std::max(t, sib.t);  // the loser of this match may be the runner-up
        const std::uint32_t lose_slot = sib.slot ^ ((slot ^ sib.slot) & mask);
        const std::uint32_t second = 0u - static_cast<std::uint32_t>(lose_t < t2);
        t2 = std::min(t2, lose_t);
        slot2 ^= (slot2 ^ lose_slot) & second;
      }
      t = std::min(t, sib.t);
      slot ^= (slot ^ sib.slot) & mask;
      node_[k >> 1] = Node{t, slot, 0};
    }
    if constexpr (Hint) hint_ = slot2;
  }
  // Node k := the earlier of its children (branch-free: select by index).
  void pull(std::size_t k) {
    const std::size_t c = 2 * k;
    node_[k] = node_[c + (node_[c + 1].t < node_[c].t)];
  }

  std::size_t n_ = 0, nb_ = 0;
  std::uint32_t hint_ = 0;
  bool hinting_ = false;
  std::vector<TimeLine, HugePageAllocator<TimeLine>> time_lines_;  // slot times; padding slots stay at +inf
  std::vector<NodeLine, HugePageAllocator<NodeLine>>
      node_lines_;  // tree nodes, cache-line aligned: siblings share a line
  double* time_ = nullptr;
  Node* node_ = nullptr;
};

}  // namespace shockgas::particles
