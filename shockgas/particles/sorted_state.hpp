#pragma once
// A chain's state sorted by x (private to particles/): what the recorder keeps
// (Bodies) and what a StateSink reads (in chunks, straight from the model).
//
// In chain order the positions never decrease (the engine's are unrolled, the
// hull's too), so on a ring the wrapped positions rise to the seam, where they
// drop by about L, and rise again: the order by x starts at the seam. Rounding
// at the wrap can leave equal neighbours misordered; then (rarely) the state is
// sorted through a copy by a stable sort of the order from the seam. On a line
// the order is the chain's, stably sorted where rounding left it out of order.
#include <array>
#include <cstddef>
#include <optional>

#include "shockgas/core/bodies.hpp"
#include "shockgas/particles/chain_view.hpp"
#include "shockgas/particles/state_sink.hpp"

namespace shockgas::particles::detail {

// The seam of wrapped positions fed in chain order, and whether the order from
// the seam is sorted. On a ring the wrapped positions drop by about L where the
// chain crosses a multiple of L, if it does (then the last position is at most
// the first: the unrolled chain spans less than L), and by rounding (a few
// units in the last place of L) where two touching bodies came out of order.
// The seam is the largest drop when there is a crossing, else the chain's
// start: not the first drop, which may be a rounding one (at N = 10^8 the
// ulp of x is 1.5e-8, and long runs leave such drops anywhere).
class SeamSearch {
 public:
  explicit SeamSearch(bool ring) : ring_(ring) {}
  void add(double w) {
    if (k_ == 0) first_ = w;
    if (k_ > 0 && w < last_) {
      ++drops_;
      if (last_ - w > largest_) largest_ = last_ - w, largest_at_ = k_;
    }
    last_ = w;
    ++k_;
  }
  std::size_t seam() const { return ring_ && drops_ > 0 && last_ <= first_ ? largest_at_ : 0; }
  std::size_t largest_drop_at() const { return largest_at_; }
  bool sorted() const { return drops_ == 0 || (ring_ && drops_ == 1 && last_ <= first_); }

 private:
  bool ring_;
  std::size_t k_ = 0, drops_ = 0, largest_at_ = 0;
  double first_ = 0, last_ = 0, largest_ = 0;
};

// The state as Bodies sorted by x, ring positions wrapped into [0, L); out of
// order from the seam, ordered in place through the window of SortedState
// (or, when that cannot order it, through a stable sort of a copy).
Bodies sorted_bodies(const ChainView& s, double L, bool ring);

// The state as a StateReader: one pass over the view per read from the seam
// (the bodies before it held back, when they are few; else two visits: from the
// seam to the end, then from the start up to it) in chunks of
// ChainChunk::capacity; the view must stay valid while the reader is used.
// Out of order from the seam (rounding), the bodies pass through a window of
// kWindow bodies kept in order (WindowedOrder), which gives the stable sort's
// order whenever no body lies more than the window behind its place (checked
// by a pass at construction); else, only then, through a sorted copy.
class SortedState final : public StateReader {
 public:
  SortedState(const ChainView& view, double L, bool ring);
  std::size_t size() const override { return view_.size(); }
  void read(const Chunk& chunk) const override;
  // Known from the construction's pass where the order from the seam is sorted.
  std::optional<std::array<double, 3>> last() const override { return last_; }
  // Whether read() orders the state through a sorted copy (bodies far out of
  // place: about 56 bytes per body more), not in one pass.
  bool through_copy() const { return !sorted_ && !windowed_; }

 private:
  const ChainView& view_;
  double L_;
  bool ring_;
  std::size_t seam_ = 0;
  bool sorted_ = true;
  bool windowed_ = false;                      // not sorted, but WindowedOrder orders it
  std::optional<std::array<double, 3>> last_;  // the last body read() hands out, where sorted_
};

}  // namespace shockgas::particles::detail
