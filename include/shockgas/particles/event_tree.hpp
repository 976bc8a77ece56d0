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
// Layout: the implicit heap of the bottom-up segment tree. Leaves sit at n..2n-1,
// node k < n is the winner of nodes 2k and 2k+1, so node 1 is the global winner
// for any n (no padding to a power of two). A node stores the winner's time and
// slot (16 bytes), so a comparison never leaves the path being refreshed. A
// collision changes at most three adjacent slots, whose paths to the root merge
// after a level or two: refresh_range walks them together.
#include <cassert>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace shockgas::particles {

class EventTree {
 public:
  static constexpr double never = std::numeric_limits<double>::infinity();

  EventTree() = default;
  explicit EventTree(std::size_t n) { reset(n); }
  EventTree(const EventTree&) = delete;  // node_ points into lines_
  EventTree& operator=(const EventTree&) = delete;

  // n slots, all at +inf.
  void reset(std::size_t n) {
    assert(n >= 1 && n < (std::size_t{1} << 31));
    n_ = n;
    lines_.assign((2 * n + 3) / 4, Line{});
    node_ = &lines_[0].node[0];
    for (std::size_t k = 0; k < 2 * n; ++k) node_[k] = Node{never, 0, 0};
    for (std::size_t i = 0; i < n; ++i) node_[n + i].slot = static_cast<std::uint32_t>(i);
    rebuild();
  }
  // Recomputes every internal node, O(n): after many set() calls.
  void rebuild() {
    for (std::size_t k = n_ - 1; k >= 1; --k) pull(k);
  }

  std::size_t size() const { return n_; }
  double time(std::size_t slot) const { return node_[n_ + slot].t; }
  std::size_t top() const { return node_[1].slot; }
  double top_time() const { return node_[1].t; }

  void set(std::size_t slot, double t) { node_[n_ + slot].t = t; }

  // Refreshes the path of one slot.
  void refresh_path(std::size_t slot) {
    if (n_ > 1) climb(n_ + slot);
  }
  // Refreshes slots lo..hi (hi - lo small): the paths merge within a few levels.
  // Children are refreshed before parents: each level in decreasing order.
  void refresh_range(std::size_t lo, std::size_t hi) {
    assert(lo <= hi && hi < n_);
    if (n_ == 1) return;
    std::size_t a = n_ + lo, b = n_ + hi;
    while (a != b) {  // leaves may sit at two depths: a can reach the root first
      a = a > 1 ? a >> 1 : 1;
      b >>= 1;
      for (std::size_t k = b; k >= a; --k) pull(k);
    }
    climb(a);
  }
  // Hints the cache about slot's leaf-to-root path (the deep levels miss).
  void prefetch_path(std::size_t slot) const {
    for (std::size_t k = n_ + slot; k >= 64; k >>= 1) __builtin_prefetch(&node_[k], 1);
  }

 private:
  struct Node {
    double t;            // winner's event time
    std::uint32_t slot;  // winner's slot
    std::uint32_t pad;
  };
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

  std::size_t n_ = 0;
  struct alignas(64) Line {
    Node node[4];
  };
  // Node storage aligned to cache lines, so siblings 2k, 2k+1 share a line.
  std::vector<Line> lines_;
  Node* node_ = nullptr;
};

}  // namespace shockgas::particles
