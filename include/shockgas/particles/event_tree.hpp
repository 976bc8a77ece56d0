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
#include <cassert>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "shockgas/particles/huge_page_allocator.hpp"

namespace shockgas::particles {

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

  // Refreshes the path of one slot.
  void refresh_path(std::size_t slot) { refresh_blocks(slot / block, slot / block); }
  // Refreshes slots lo..hi (hi - lo small).
  void refresh_range(std::size_t lo, std::size_t hi) {
    assert(lo <= hi && hi < n_);
    refresh_blocks(lo / block, hi / block);
  }
  // Hints the cache about a slot's block and the deep part of its path.
  void prefetch_path(std::size_t slot) const {
    __builtin_prefetch(&time_[slot], 1);
    for (std::size_t k = nb_ + slot / block; k >= 4096; k >>= 1) __builtin_prefetch(&node_[k], 1);
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
  void climb(std::size_t k) {
    double t = node_[k].t;
    std::uint32_t slot = node_[k].slot;
    for (; k > 1; k >>= 1) {
      const Node& sib = node_[k ^ 1];
      const bool take = sib.t < t;  // ties: either is a valid winner
      t = take ? sib.t : t;
      slot ^= (slot ^ sib.slot) & (0u - static_cast<std::uint32_t>(take));  // no branch to mispredict
      node_[k >> 1] = Node{t, slot, 0};
    }
  }
  // Node k := the earlier of its children (branch-free: select by index).
  void pull(std::size_t k) {
    const std::size_t c = 2 * k;
    node_[k] = node_[c + (node_[c + 1].t < node_[c].t)];
  }

  std::size_t n_ = 0, nb_ = 0;
  std::vector<TimeLine, HugePageAllocator<TimeLine>> time_lines_;  // slot times; padding slots stay at +inf
  std::vector<NodeLine, HugePageAllocator<NodeLine>>
      node_lines_;  // tree nodes, cache-line aligned: siblings share a line
  double* time_ = nullptr;
  Node* node_ = nullptr;
};

}  // namespace shockgas::particles
