#pragma once
// The earliest of the 16 slot times of one block, two cache lines (private to
// particles/), for the event tree's leaves (event_tree.hpp), in the widest SIMD
// the build targets (cmake/Native.cmake): AVX-512, else SSE2, else a scalar
// tournament.
//
// Contract: times are +0.0 or greater, or +inf; never -0.0 or NaN (whose keys
// would sort apart from the numbers' order). The result is the smallest time
// (as its integer key, see key_of) and the first lane holding it: the same for
// every path, to the bit, because a minimum and an equality compare are exact
// (test EventTree.ReplaceThreeIsSetAndRefresh, run by both builds).
#include <cstdint>

#include "shockgas/core/bit_cast.hpp"
#include "shockgas/particles/slot_times.hpp"

#if defined(__AVX512F__)
#include <immintrin.h>
#elif defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace shockgas::particles::detail {

// Event times are >= 0 (or +inf), and for such doubles the order of their bit
// patterns read as signed integers is the order of the numbers: an integer
// compare and a conditional move take 2 cycles against 4 for a floating-point
// minimum, which matters on the tree's serial chains. (A NaN would sort after
// +inf: never.)
using TimeKey = std::int64_t;
inline TimeKey key_of(double t) { return shockgas::bit_cast<TimeKey>(t); }

// (t, slot) := (u, at) if u < t: compare and two conditional moves. Written as
// assembly on x86-64 because GCC 12 turns the equivalent ternaries into
// branches, which mispredict half the time here. Ties keep (t, slot).
inline void take_earlier(TimeKey& t, std::uint32_t& slot, TimeKey u, std::uint32_t at) {
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

struct LaneWinner {
  TimeKey t;           // the smallest time, as key_of
  std::uint32_t lane;  // the first of the 16 lanes that hold it
};

// (t, lane) := (u, at) if (u, at) < (t, lane) lexicographically: the earliest
// time, and of equal times the first lane. A compare of the lanes and a
// subtract with borrow of the times (the two-word compare of a 128-bit integer)
// and two conditional moves, as take_earlier.
inline void take_earlier_lane(TimeKey& t, std::uint32_t& lane, TimeKey u, std::uint32_t at) {
#if defined(__x86_64__)
  TimeKey diff;  // u - t - borrow, for the flags (early clobber: written before u is read last)
  asm("movq %[u], %[diff]\n\tcmpl %[lane], %[at]\n\tsbbq %[t], %[diff]\n\t"
      "cmovlq %[u], %[t]\n\tcmovll %[at], %[lane]"
      : [t] "+r"(t), [lane] "+r"(lane), [diff] "=&r"(diff)
      : [u] "r"(u), [at] "r"(at)
      : "cc");
#else
  const bool take = u < t || (u == t && at < lane);
  lane = take ? at : lane;
  t = take ? u : t;
#endif
}

// The slot times of one block (SlotTimes::block): the code below reads them as
// two lines of 8.
inline constexpr std::uint32_t block_lanes = SlotTimes::block;
static_assert(block_lanes == 16, "lane_winner and ThreeTimes read a block as two lines of 8");

#if defined(__AVX512F__)
// The 16 times of a block in two registers (lanes 0-7 and 8-15): the smallest by
// a reduction of packed minima, its first lane by equality masks. (Halves by
// __builtin_shufflevector: GCC 12 warns of an undefined operand inside the
// intrinsics for them.)
[[gnu::always_inline]] inline LaneWinner lane_winner(__m512d low, __m512d high) {
  const __m512d m8 = _mm512_maskz_min_pd(0xFF, low, high);  // (the unmasked form warns as above)
  const __m256d m4 =
      _mm256_min_pd(__builtin_shufflevector(m8, m8, 0, 1, 2, 3), __builtin_shufflevector(m8, m8, 4, 5, 6, 7));
  const __m128d m2 = _mm_min_pd(__builtin_shufflevector(m4, m4, 0, 1), __builtin_shufflevector(m4, m4, 2, 3));
  const __m128d m1 = _mm_min_sd(m2, _mm_unpackhi_pd(m2, m2));
  const __m512d all = _mm512_set1_pd(_mm_cvtsd_f64(m1));
  const unsigned mask = static_cast<unsigned>(_mm512_cmpeq_pd_mask(low, all)) |
                        static_cast<unsigned>(_mm512_cmpeq_pd_mask(high, all)) << 8;
  return {key_of(_mm_cvtsd_f64(m1)), static_cast<std::uint32_t>(std::countr_zero(mask))};
}
#endif

// The earliest of the 16 times at t (a 128-byte aligned block).
[[gnu::always_inline]] inline LaneWinner lane_winner(const double* t) {
#if defined(__AVX512F__)
  return lane_winner(_mm512_load_pd(t), _mm512_load_pd(t + 8));
#elif defined(__SSE2__)
  // Packed minima, then the first lane by equality masks: the same winner as the
  // pairwise tournament below, in fewer instructions. (Loading each pair as two
  // 8-byte halves, which the 8-byte stores of a collision can forward, measured
  // no faster: 0.99x, 5 pairs at N = 10^6, t = 10^3.)
  __m128d pair[8];
  for (int k = 0; k < 8; ++k) pair[k] = _mm_load_pd(t + 2 * k);
  const __m128d m4 = _mm_min_pd(_mm_min_pd(_mm_min_pd(pair[0], pair[1]), _mm_min_pd(pair[2], pair[3])),
                                _mm_min_pd(_mm_min_pd(pair[4], pair[5]), _mm_min_pd(pair[6], pair[7])));
  const __m128d m1 = _mm_min_sd(m4, _mm_unpackhi_pd(m4, m4));
  const __m128d m = _mm_unpacklo_pd(m1, m1);
  unsigned mask = 0;
  for (int k = 0; k < 8; ++k)
    mask |= static_cast<unsigned>(_mm_movemask_pd(_mm_cmpeq_pd(pair[k], m))) << 2 * k;
  return {key_of(_mm_cvtsd_f64(m1)), static_cast<std::uint32_t>(std::countr_zero(mask))};
#else
  // Rounds of matches between neighbours: ties keep the left, so the first lane wins.
  TimeKey k[block_lanes];
  std::uint32_t at[block_lanes];
  for (std::uint32_t l = 0; l < block_lanes; ++l) k[l] = key_of(t[l]), at[l] = l;
  for (std::uint32_t stride = 1; stride < block_lanes; stride *= 2)
    for (std::uint32_t l = 0; l < block_lanes; l += 2 * stride)
      take_earlier(k[l], at[l], k[l + stride], at[l + stride]);
  return {k[0], at[0]};
#endif
}

#if defined(__AVX512F__)
// A collision's three new slot times (tp, +inf, tj for slots p, p + 1, p + 2)
// merged into the lines that hold them, in registers. o = p mod 16: the slots
// are lanes o .. o + 2 of the block, lines 0 and 1, and past lane 15 the first
// lanes of the next block's line 0 (line 2 here).
class ThreeTimes {
 public:
  ThreeTimes(std::uint32_t o, double tp, double never, double tj)
      : values_(spread(_mm_set_pd(never, tp), _mm_set1_pd(tj))),
        // Lane l of every line takes value (l - o) mod 8: the lanes of slots p,
        // p + 1, p + 2 take 0, 1, 2 (the permute reads 3 bits).
        index_(_mm512_sub_epi64(_mm512_setr_epi64(0, 1, 2, 3, 4, 5, 6, 7), _mm512_set1_epi64(o))),
        lanes_(0b111u << o) {}
  // Whether the three lie in one block.
  bool one_block() const { return lanes_ < (1u << block_lanes); }
  // Line k (0, 1 or 2), as loaded, with the three slots replaced.
  __m512d merged(__m512d line, int k) const {
    return _mm512_mask_permutexvar_pd(line, lanes(k), index_, values_);
  }
  // The same with +inf in their places: the block's other slots, whose minimum
  // does not wait for the new times (see earliest_with).
  __m512d cleared(__m512d line, int k) const {
    return _mm512_mask_mov_pd(line, lanes(k), _mm512_set1_pd(__builtin_inf()));
  }
  // The earliest of block 0 from that of its cleared lines: the lexicographic
  // minimum of (time, lane) over it and the new times' lanes. The +inf put in
  // their places changes nothing: (+inf, o) and (+inf, o + 2) are never earlier
  // than (tp, o) and (tj, o + 2), and (+inf, o + 1), slot p + 1's true time,
  // never earlier than (+inf, o).
  LaneWinner earliest_with(LaneWinner rest, TimeKey tp, TimeKey tj) const {
    const auto o = static_cast<std::uint32_t>(std::countr_zero(lanes_));
    take_earlier_lane(rest.t, rest.lane, tp, o);
    take_earlier_lane(rest.t, rest.lane, tj, o + 2);
    return rest;
  }

 private:
  // (a0, a1, b0) in lanes 0, 1, 2 (the others unused).
  static __m512d spread(__m128d a, __m128d b) {
    const __m256d four = __builtin_shufflevector(a, b, 0, 1, 2, 3);
    return __builtin_shufflevector(four, four, 0, 1, 2, 3, 0, 1, 2, 3);
  }
  __mmask8 lanes(int k) const { return static_cast<__mmask8>(lanes_ >> 8 * k); }
  __m512d values_;
  __m512i index_;
  unsigned lanes_;  // bit l: lane l of the block (lines 0 and 1), bit 16 + l: of the next
};
#endif

}  // namespace shockgas::particles::detail
