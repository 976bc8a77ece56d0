#pragma once
// Event queue of the particle engine (private to particles/): a tournament
// (winner) tree over the pair slots.
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
// the global winner for any nb (no padding to a power of two, which would put
// every leaf at the deepest level). A node stores the winner's time and slot (12
// bytes), so a comparison never leaves the path being refreshed. A collision
// changes at most three adjacent slots, nearly always in one block: one line of
// times, then one path to the root. The tree is 3 bytes per slot (8 for the
// times), so at N = 10^6 its upper levels stay in cache.
#include <algorithm>
#include <bit>
#include <cassert>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "huge_page_allocator.hpp"

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

class EventTree {
 public:
  static constexpr double never = std::numeric_limits<double>::infinity();
  static constexpr std::size_t block = 8;  // slot times per cache line (block_winner is written for 8)

  EventTree() = default;
  explicit EventTree(std::size_t n) { reset(n); }
  EventTree(const EventTree&) = delete;  // time_ points into owned lines
  EventTree& operator=(const EventTree&) = delete;

  // n slots, all at +inf.
  void reset(std::size_t n) {
    assign(n, [](std::size_t) { return never; });
  }
  // n slots, slot i at time_of(i); O(n). Reuses the memory of a larger tree.
  template <class F>
  void assign(std::size_t n, F&& time_of) {
    assert(n >= 1 && n < (std::size_t{1} << 31));
    n_ = n;
    nb_ = (n + block - 1) / block;
    hinting_ = n >= hint_slots;
    hint_ = 0;
    time_lines_.resize(nb_);
    time_ = &time_lines_[0].t[0];
    for (std::size_t i = 0; i < n; ++i) time_[i] = time_of(i);
    for (std::size_t i = n; i < nb_ * block; ++i) time_[i] = never;
    key_.resize(2 * nb_);
    win_.resize(2 * nb_);
    rebuild();
  }
  // Recomputes every block and internal node, O(n): after many set() calls.
  void rebuild() {
    for (std::size_t b = 0; b < nb_; ++b) put(nb_ + b, block_winner(b));
    for (std::size_t k = nb_ - 1; k >= 1; --k) pull(k);
  }

  std::size_t size() const { return n_; }
  double time(std::size_t slot) const { return time_[slot]; }
  std::size_t top() const { return win_[1]; }
  double top_time() const { return std::bit_cast<double>(key_[1]); }

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
    for (std::size_t k = nb_ + slot / block; k >= 4096; k >>= 1)
      prefetch_line(&key_[k]), prefetch_line(&win_[k]);
  }

 private:
  // Event times are >= 0 (or +inf), and for such doubles the order of their bit
  // patterns read as signed integers is the order of the numbers: an integer
  // compare and a conditional move take 2 cycles against 4 for a floating-point
  // minimum, which matters on the climb's serial chain. (A NaN would sort after
  // +inf: never.)
  using Key = std::int64_t;
  static Key key_of(double t) { return std::bit_cast<Key>(t); }
  // (t, slot) := (u, at) if u < t: compare and two conditional moves. Written as
  // assembly on x86-64 because GCC 12 turns the equivalent ternaries into
  // branches, which mispredict half the time here. Ties keep (t, slot).
  static void take_earlier(Key& t, std::uint32_t& slot, Key u, std::uint32_t at) {
#if defined(__x86_64__)
    asm("cmpq %[u], %[t]\n\tcmovgq %[u], %[t]\n\tcmovgl %[at], %[slot]"
        : [t] "+r"(t), [slot] "+r"(slot)
        : [u] "r"(u), [at] "r"(at)
        : "cc");
#else
    const bool take = u < t;
    slot = take ? at : slot;
    t = take ? u : t;
#endif
  }
  struct Node {
    Key t;               // winner's event time, as key_of
    std::uint32_t slot;  // winner's slot
  };
  struct alignas(64) TimeLine {
    double t[block];
  };

  // The earliest slot of block b: a tournament of depth 3 over one cache line.
  Node block_winner(std::size_t b) const {
    const double* t = time_ + b * block;
    Key k0 = key_of(t[0]), k1 = key_of(t[1]), k2 = key_of(t[2]), k3 = key_of(t[3]);
    Key k4 = key_of(t[4]), k5 = key_of(t[5]), k6 = key_of(t[6]), k7 = key_of(t[7]);
    std::uint32_t a0 = 0, a2 = 2, a4 = 4, a6 = 6;
    take_earlier(k0, a0, k1, 1);
    take_earlier(k2, a2, k3, 3);
    take_earlier(k4, a4, k5, 5);
    take_earlier(k6, a6, k7, 7);
    take_earlier(k0, a0, k2, a2);
    take_earlier(k4, a4, k6, a6);
    take_earlier(k0, a0, k4, a4);
    return Node{k0, static_cast<std::uint32_t>(b * block) + a0};
  }

  void put(std::size_t k, const Node& node) {
    key_[k] = node.t;
    win_[k] = node.slot;
  }

  // Blocks a..b (b - a <= 1 in use) and their common path to the root.
  void refresh_blocks(std::size_t a, std::size_t b) {
    if (a == b) {  // nearly always
      put(nb_ + a, block_winner(a));
      return climb(nb_ + a);
    }
    std::size_t ka = nb_ + a, kb = nb_ + b;
    for (std::size_t k = ka; k <= kb; ++k) put(k, block_winner(k - nb_));
    while (ka != kb) {  // leaves may sit at two depths: ka can reach the root first
      ka = ka > 1 ? ka >> 1 : 1;
      kb >>= 1;
      for (std::size_t k = kb; k >= ka; --k) pull(k);
    }
    climb(ka);
  }

  // Refreshes the ancestors of node k (k itself up to date). The winner so far
  // stays in registers; only the siblings are loaded, and their addresses do not
  // depend on the comparisons, so the loads overlap. Selects by conditional
  // moves: no branch to mispredict.
  //
  // On the way it keeps the runner-up among node k and the siblings (the winners
  // of the subtrees that partition the rest of the tree): the slot of the event
  // after the next one whenever that lies outside the next one's subtree (for
  // random positions, with probability 1 - sum_j 4^-j = 2/3). hint() serves it
  // for prefetching.
  void climb(std::size_t k) { hinting_ ? climb<true>(k) : climb<false>(k); }
  template <bool Hint>
  void climb(std::size_t k) {
    Key t = key_[k];
    std::uint32_t slot = win_[k];
    Key t2 = key_of(never);
    std::uint32_t slot2 = slot;
    for (; k > 1; k >>= 1) {
      const Key sib_t = key_[k ^ 1];
      const std::uint32_t sib_slot = win_[k ^ 1];
      const Key old_t = t;
      const std::uint32_t old_slot = slot;
      take_earlier(t, slot, sib_t, sib_slot);
      if constexpr (Hint) {
        // The loser of this match (the one of the two not kept) may be the runner-up.
        take_earlier(t2, slot2, old_t ^ sib_t ^ t, old_slot ^ sib_slot ^ slot);
      }
      key_[k >> 1] = t;
      win_[k >> 1] = slot;
    }
    if constexpr (Hint) hint_ = slot2;
  }
  // Node k := the earlier of its children (branch-free: select by index).
  void pull(std::size_t k) {
    const std::size_t c = 2 * k;
    const std::size_t w = c + (key_[c + 1] < key_[c]);
    key_[k] = key_[w];
    win_[k] = win_[w];
  }

  std::size_t n_ = 0, nb_ = 0;
  std::uint32_t hint_ = 0;
  bool hinting_ = false;
  std::vector<TimeLine, HugePageAllocator<TimeLine>> time_lines_;  // slot times; padding slots stay at +inf
  // Node k: its winner's key and slot, in two arrays (index arithmetic the
  // addressing modes do for free); siblings share cache lines.
  std::vector<Key, HugePageAllocator<Key>> key_;
  std::vector<std::uint32_t, HugePageAllocator<std::uint32_t>> win_;
  double* time_ = nullptr;
};

}  // namespace shockgas::particles
