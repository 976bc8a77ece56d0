#pragma once
// Event queue of the particle engine (private to particles/): a tournament
// (winner) tree over a run of pair slots.
//
// Contract:
//  * SlotTimes holds one predicted event time per pair slot (pair i = body i and
//    its right neighbour), +inf for "no event". It is the one copy of the times:
//    the global queue and the window domains all read and write it.
//  * An EventTree ranks the slots first..last of a SlotTimes (on a ring the run
//    may wrap past the last slot to slot 0: last < first). Several trees may
//    rank disjoint runs of the same SlotTimes at once, from different threads.
//  * set(i, t) replaces slot i's time; the tree is consistent only after the
//    matching refresh (refresh_path(i), or refresh(a, b) for a slot a and the
//    slot b after it, covering every slot set since the last refresh).
//  * top() is a slot with the smallest time, O(1). Of tied slots it is the
//    earlier one within a block and, above, the one the refreshes left in place:
//    the same for the same sequence of operations.
//
// Layout. The times are stored in blocks of 16 (two cache lines, which the
// second-level cache fetches as a pair); the tree is over the blocks of the run:
// the implicit heap of the bottom-up segment tree, leaves at nb..2nb-1 (nb
// blocks), node k < nb the winner of nodes 2k and 2k+1, so node 1 is the winner
// for any nb (no padding to a power of two, which would put every leaf at the
// deepest level; node 0 is a sink, see climb_leaf). A node stores the winner's
// time and slot (12 bytes), so a comparison never leaves the path being
// refreshed. A collision changes at most three adjacent slots, in one block but
// for one collision in eight: one block of times, then one path to the root. (Blocks of 16 rather than one
// line of 8: a level less to climb, and half as many collisions that span two blocks.) The tree is 1.5 bytes
// per slot (8 for the times), so at N = 10^6 its upper levels stay in cache. A run's first and last blocks
// may be shared with the neighbouring runs: their winners read only the run's own slots.
#include <algorithm>
#include <bit>
#include <cassert>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "shockgas/core/bit_cast.hpp"
#include "shockgas/particles/block_minimum.hpp"
#include "shockgas/particles/slot_times.hpp"

namespace shockgas::particles {

namespace detail {
struct StateIo;
}

class EventTree {
 public:
  static constexpr double never = SlotTimes::never;
  static constexpr std::size_t block = SlotTimes::block;
  // Node storage of a tree of nb blocks: 2 nb keys and 2 nb slots.
  static constexpr std::size_t nodes(std::size_t nb) { return 2 * nb; }
  using Key = detail::TimeKey;

  EventTree() = default;
  // A standalone tree over n slots of its own, all at +inf.
  explicit EventTree(std::size_t n) { reset(n); }
  EventTree(const EventTree&) = delete;
  EventTree& operator=(const EventTree&) = delete;
  EventTree(EventTree&& other) noexcept { *this = std::move(other); }
  EventTree& operator=(EventTree&& other) noexcept {
    const bool own_times = other.times_ == &other.own_times_;
    const bool own_nodes = other.key_ == other.own_key_.data();
    times_ = other.times_, time_ = other.time_, first_ = other.first_, last_ = other.last_;
    b0_ = other.b0_, all_blocks_ = other.all_blocks_, nb_ = other.nb_;
    head_partial_ = other.head_partial_, tail_partial_ = other.tail_partial_;
    hint_ = other.hint_, hinting_ = other.hinting_, leaf_depth_ = other.leaf_depth_;
    key_ = other.key_, win_ = other.win_;
    own_key_ = std::move(other.own_key_), own_win_ = std::move(other.own_win_);
    own_times_ = std::move(other.own_times_);
    if (own_times) times_ = &own_times_, time_ = own_times_.data();  // the storage moved, its owner did not
    if (own_nodes) key_ = own_key_.data(), win_ = own_win_.data();
    return *this;
  }

  // Standalone: n slots of its own at +inf.
  void reset(std::size_t n) {
    own_times_.reset(n);
    attach(own_times_, 0, n - 1);
  }
  // Ranks slots first..last of times (wrapping past the end if last < first),
  // as they are now; O(length). Nodes in storage of its own, reused.
  void attach(SlotTimes& times, std::size_t first, std::size_t last) {
    const std::size_t nb = blocks_of(times, first, last);
    own_key_.resize(nodes(nb));
    own_win_.resize(nodes(nb));
    attach(times, first, last, own_key_.data(), own_win_.data());
  }
  // The same with node storage from the caller: nodes(number of blocks) each.
  void attach(SlotTimes& times, std::size_t first, std::size_t last, Key* keys, std::uint32_t* wins) {
    assert(first < times.size() && last < times.size() &&
           std::uint64_t{times.size()} < (std::uint64_t{1} << 32));
    times_ = &times;
    time_ = times.data();
    first_ = first;
    last_ = last;
    b0_ = first / block;
    all_blocks_ = times.blocks();
    nb_ = blocks_of(times, first, last);
    head_partial_ = first % block != 0;
    tail_partial_ = (last + 1) % block != 0 && last + 1 != times.size();
    hinting_ = nb_ * block >= hint_slots;
    leaf_depth_ = static_cast<std::uint32_t>(std::bit_width(2 * nb_ - 1) - 1);
    hint_ = static_cast<std::uint32_t>(first);
    key_ = keys;
    win_ = wins;
    rebuild();
  }
  // Number of blocks of the run first..last of times.
  static std::size_t blocks_of(const SlotTimes& times, std::size_t first, std::size_t last) {
    const std::size_t a = first / block, b = last / block;
    return first <= last ? b - a + 1 : times.blocks() - a + b + 1;
  }

  // Recomputes every block and internal node, O(length): after many set() calls.
  void rebuild() {
    put(0, Node{detail::key_of(never), 0});  // the sink of climb_leaf
    for (std::size_t p = 0; p < nb_; ++p) put(nb_ + p, block_winner(p, block_at(p)));
    for (std::size_t k = nb_ - 1; k >= 1; --k) pull(k);
  }

  // The node arrays (for prefetching): nodes() keys and slots.
  const Key* node_keys() const { return key_; }
  const std::uint32_t* node_slots() const { return win_; }
  std::size_t node_count() const { return nodes(nb_); }
  std::size_t first() const { return first_; }
  std::size_t last() const { return last_; }
  double time(std::size_t slot) const { return time_[slot]; }
  std::size_t top() const { return win_[1]; }
  double top_time() const { return shockgas::bit_cast<double>(key_[1]); }

  void set(std::size_t slot, double t) { time_[slot] = t; }
  // With hinting() (trees of hint_slots slots or more, too large for the caches):
  // a slot likely to hold the second-earliest time after the last refresh (see
  // climb), for prefetching only, never relied on. Otherwise the first slot.
  static constexpr std::size_t hint_slots = std::size_t{1} << 18;
  bool hinting() const { return hinting_; }
  std::size_t hint() const { return hint_; }

  // Refreshes the path of one slot.
  void refresh_path(std::size_t slot) { refresh_block(slot / block); }
  // Refreshes slots a and b, where b is a or a slot after it in the run and the
  // slots set since the last refresh lie between them (b - a small). Past the
  // ring's end (b < a) the last block may lie between their blocks: with N = 1
  // (mod 16) it holds slot N - 1 alone, and a bounce's slots N - 2, N - 1, 0
  // span three blocks (left stale, that block's old winner stayed on top: the
  // same pair met again at the same time until the run stopped as a stall).
  [[gnu::always_inline]] void refresh(std::size_t a, std::size_t b) {
    const std::size_t ba = a / block, bb = b / block;
    if (ba == bb) [[likely]]
      return refresh_block(ba);
    if (bb < ba && ba + 1 < all_blocks_) [[unlikely]]
      refresh_block(all_blocks_ - 1);
    refresh_two(position(ba), position(bb));
  }
  // Slots p, p + 1 and p + 2 (past the last slot: 0, 1) := tp, +inf, tj, then
  // refreshed: a bounce's three slots, all in the run, as set() thrice and
  // refresh(p, p + 2). With AVX-512 the times are merged into their block's two
  // lines in registers and each line is stored whole (the one the three miss
  // unchanged): no load of a line just written by narrower stores, which cannot
  // be served from them and waits until they reach the cache (a failed store
  // forward). The minimum of the block's other slots is taken from the lines as
  // loaded, so that only two compares wait for tp and tj, not a reduction of 16.
  [[gnu::always_inline]] void replace_three(std::size_t p, double tp, double tj) {
#if defined(__AVX512F__)
    const std::size_t b = p / block, pos = position(b);
    const detail::ThreeTimes three(p % block, tp, never, tj);
    const std::size_t blocks = three.one_block() ? 1 : 2;
    if (p + 2 < times_->size() && owns_blocks(pos, blocks)) [[likely]] {
      double* line = time_ + b * block;
      const __m512d low = _mm512_load_pd(line), high = _mm512_load_pd(line + 8);
      const __m512d new_low = three.merged(low, 0), new_high = three.merged(high, 1);
      _mm512_store_pd(line, new_low);
      _mm512_store_pd(line + 8, new_high);
      if (blocks == 1) [[likely]] {
        const auto rest = detail::lane_winner(three.cleared(low, 0), three.cleared(high, 1));
        const Node leaf = node_of(three.earliest_with(rest, detail::key_of(tp), detail::key_of(tj)), b);
        put(nb_ + pos, leaf);
        return climb_leaf(nb_ + pos, leaf);
      }
      const __m512d next = three.merged(_mm512_load_pd(line + 16), 2);
      _mm512_store_pd(line + 16, next);
      return refresh_two(pos, pos + 1, node_of(detail::lane_winner(new_low, new_high), b),
                         node_of(detail::lane_winner(next, _mm512_load_pd(line + 24)), b + 1));
    }
#endif
    const std::size_t n = times_->size(), i = p + 1 == n ? 0 : p + 1, j = i + 1 == n ? 0 : i + 1;
    set(p, tp);
    set(i, never);
    set(j, tj);
    refresh(p, j);
  }
  // Hints the cache about a slot's block and the deep part of its path.
  void prefetch_path(std::size_t slot) const {
    const double* times = time_ + slot / block * block;
    prefetch_line(times), prefetch_line(times + 8);
    for (std::size_t k = nb_ + position(slot / block); k >= 4096; k >>= 1)
      prefetch_line(&key_[k]), prefetch_line(&win_[k]);
  }

 private:
  friend struct detail::StateIo;  // saves and restores the nodes as they are
  struct Node {
    Key t;               // winner's event time, as key_of
    std::uint32_t slot;  // winner's slot
  };

  // Leaf position of block b in the run.
  std::size_t position(std::size_t b) const { return b >= b0_ ? b - b0_ : b + all_blocks_ - b0_; }
  std::size_t block_at(std::size_t p) const {
    const std::size_t b = b0_ + p;
    return b < all_blocks_ ? b : b - all_blocks_;
  }

  // The earliest slot of block b, at position p (block_minimum.hpp).
  [[gnu::always_inline]] Node block_winner(std::size_t p, std::size_t b) const {
    if (p - 1 >= nb_ - 2) [[unlikely]]  // the first or the last (or nb <= 2)
      if ((p == 0 && head_partial_) || (p == nb_ - 1 && tail_partial_)) return partial_winner(p);
    return node_of(detail::lane_winner(time_ + b * block), b);
  }
  static Node node_of(detail::LaneWinner w, std::size_t b) {
    return Node{w.t, static_cast<std::uint32_t>(b * block) + w.lane};
  }
  // Whether the blocks at positions pos .. pos + count - 1 hold only the run's
  // slots (and padding): the first and last may be shared with a neighbouring run.
  bool owns_blocks(std::size_t pos, std::size_t count) const {
    return (pos > 0 || !head_partial_) && (pos + count < nb_ || !tail_partial_);
  }
  // A first or last block shared with a neighbouring run: only the run's slots
  // are read (another thread may be writing the others).
  [[gnu::noinline, gnu::cold]] Node partial_winner(std::size_t p) const {
    const std::size_t b = block_at(p);
    std::size_t lo = b * block, hi = lo + block;  // slots lo..hi-1 of the run
    if (p == 0 && head_partial_) lo = first_;
    if (p == nb_ - 1 && tail_partial_) hi = last_ + 1;
    Node best{detail::key_of(never), static_cast<std::uint32_t>(lo)};
    for (std::size_t s = lo; s < hi; ++s)
      detail::take_earlier(best.t, best.slot, detail::key_of(time_[s]), s);
    return best;
  }

  void put(std::size_t k, const Node& node) {
    key_[k] = node.t;
    win_[k] = node.slot;
  }

  // Block b and its path to the root.
  [[gnu::always_inline]] void refresh_block(std::size_t b) {
    const std::size_t p = position(b);
    const Node leaf = block_winner(p, b);
    put(nb_ + p, leaf);
    climb_leaf(nb_ + p, leaf);
  }
  // Adjacent leaves at positions a and b = a + 1 and their paths to the root: a
  // climb from each, the second redoing the part above the joint with both
  // leaves new. Fewer instructions were spent skipping the climb of a leaf whose
  // winner did not change, or pulling both paths in step up to the joint, but
  // on branches that no predictor knows (whether the slot that did not collide
  // beat its block's winner), in one collision of eight: N = 10^6 to t = 3 10^3,
  // one thread, 0.969 of their time.
  [[gnu::noinline]] void refresh_two(std::size_t a, std::size_t b) {
    join_paths(a, b, block_winner(a, block_at(a)), block_winner(b, block_at(b)));
  }
  // The same with the leaves' new winners wa and wb.
  [[gnu::noinline]] void refresh_two(std::size_t a, std::size_t b, Node wa, Node wb) {
    join_paths(a, b, wa, wb);
  }
  [[gnu::always_inline]] void join_paths(std::size_t a, std::size_t b, Node wa, Node wb) {
    const std::size_t ka = nb_ + a, kb = nb_ + b;
    put(ka, wa);
    put(kb, wb);
    climb_leaf(ka, wa);
    climb_leaf(kb, wb);
  }

  // Refreshes the ancestors of leaf k, whose new value is node (not reloaded from
  // where it was just stored). The winner so far stays in registers; only the
  // siblings are loaded, and their addresses do not depend on the comparisons,
  // so the loads overlap. Selects by conditional moves: no branch to mispredict.
  //
  // Without the hint it climbs leaf_depth_ levels, the depth of the deepest
  // leaves, whatever the leaf's own: a leaf one level higher (nb not a power of
  // two) makes its last match against node 0 and writes it there, a sink no one
  // reads. The unrolled climb is entered by an indirect jump on the number of
  // levels: one number per tree is predicted, where the depth of a random leaf
  // was not (N = 10^6 to t = 10^4, one thread: 0.983 of the time).
  //
  // With the hint (trees too large for the caches) it keeps on the way the
  // runner-up among node k and the siblings (the winners of the subtrees that
  // partition the rest of the tree): the slot of the event after the next one
  // whenever that lies outside the next one's subtree (for random positions,
  // with probability 1 - sum_j 4^-j = 2/3). hint() serves it for prefetching.
  [[gnu::always_inline]] void climb_leaf(std::size_t k, Node node) {
    hinting_ ? climb<true>(k, node) : climb_unrolled(k, node, leaf_depth_);
  }
  // The climb without the hint (the trees of a window's domains), unrolled: one
  // case per level, no loop counter; the levels past the root go into node 0.
  [[gnu::always_inline]] void climb_unrolled(std::size_t k, Node node, std::size_t levels) {
    Key t = node.t;
    std::uint32_t slot = node.slot;
    auto level = [&]() __attribute__((always_inline)) {
      const Key sib_t = key_[k ^ 1];
      const std::uint32_t sib_slot = win_[k ^ 1];
      detail::take_earlier(t, slot, sib_t, sib_slot);
      k >>= 1;
      key_[k] = t;
      win_[k] = slot;
    };
    // std::size_t: 8 bytes on 64-bit hosts, 4 in the lab's WebAssembly build.
    static_assert(sizeof(std::size_t) >= 4);
    switch (levels) {  // the tree has fewer than 2^31 nodes
      // clang-format off
      case 30: level(); [[fallthrough]]; case 29: level(); [[fallthrough]]; case 28: level(); [[fallthrough]];
      case 27: level(); [[fallthrough]]; case 26: level(); [[fallthrough]]; case 25: level(); [[fallthrough]];
      case 24: level(); [[fallthrough]]; case 23: level(); [[fallthrough]]; case 22: level(); [[fallthrough]];
      case 21: level(); [[fallthrough]]; case 20: level(); [[fallthrough]]; case 19: level(); [[fallthrough]];
      case 18: level(); [[fallthrough]]; case 17: level(); [[fallthrough]]; case 16: level(); [[fallthrough]];
      case 15: level(); [[fallthrough]]; case 14: level(); [[fallthrough]]; case 13: level(); [[fallthrough]];
      case 12: level(); [[fallthrough]]; case 11: level(); [[fallthrough]]; case 10: level(); [[fallthrough]];
      case 9: level(); [[fallthrough]]; case 8: level(); [[fallthrough]]; case 7: level(); [[fallthrough]];
      case 6: level(); [[fallthrough]]; case 5: level(); [[fallthrough]]; case 4: level(); [[fallthrough]];
      case 3: level(); [[fallthrough]]; case 2: level(); [[fallthrough]]; case 1: level(); [[fallthrough]];
      default: break;
        // clang-format on
    }
  }
  template <bool Hint>
  void climb(std::size_t k, Node node) {
    Key t = node.t;
    std::uint32_t slot = node.slot;
    Key t2 = detail::key_of(never);
    std::uint32_t slot2 = slot;
    for (; k > 1; k >>= 1) {
      const Key sib_t = key_[k ^ 1];
      const std::uint32_t sib_slot = win_[k ^ 1];
      const Key old_t = t;
      const std::uint32_t old_slot = slot;
      detail::take_earlier(t, slot, sib_t, sib_slot);
      if constexpr (Hint) {
        // The loser of this match (the one of the two not kept) may be the runner-up.
        detail::take_earlier(t2, slot2, old_t ^ sib_t ^ t, old_slot ^ sib_slot ^ slot);
      }
      key_[k >> 1] = t;
      win_[k >> 1] = slot;
    }
    if constexpr (Hint) hint_ = slot2;
  }
  // Node k := the earlier of its children (branch-free: select by index; ties go left).
  void pull(std::size_t k) {
    const std::size_t c = 2 * k;
    const std::size_t w = c + (key_[c + 1] < key_[c]);
    key_[k] = key_[w];
    win_[k] = win_[w];
  }

  SlotTimes* times_ = nullptr;
  double* time_ = nullptr;  // times_->data()
  std::size_t first_ = 0, last_ = 0;
  std::size_t b0_ = 0, all_blocks_ = 0, nb_ = 0;
  bool head_partial_ = false, tail_partial_ = false;
  std::uint32_t hint_ = 0;
  bool hinting_ = false;
  std::uint32_t leaf_depth_ = 0;  // levels above the deepest leaves
  // Node k: its winner's key and slot, in two arrays (index arithmetic the
  // addressing modes do for free); siblings share cache lines.
  Key* key_ = nullptr;
  std::uint32_t* win_ = nullptr;
  std::vector<Key, HugePageAllocator<Key>> own_key_;
  std::vector<std::uint32_t, HugePageAllocator<std::uint32_t>> own_win_;
  SlotTimes own_times_;
};

}  // namespace shockgas::particles
