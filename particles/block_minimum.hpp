#pragma once
// The earliest of the 8 slot times of one cache line (private to particles/),
// for the event tree's leaves (event_tree.hpp), in the widest SIMD the build
// targets (cmake/Native.cmake): AVX-512, else SSE2, else a scalar tournament.
//
// Contract: times are >= 0 or +inf, never NaN. The result is the smallest time
// (as its integer key, see key_of) and the first lane holding it: the same for
// every path, to the bit, because a minimum and an equality compare are exact
// (test EventTree.ReplaceThreeIsSetAndRefresh, run by both builds).
#include <bit>
#include <cstdint>

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
inline TimeKey key_of(double t) { return std::bit_cast<TimeKey>(t); }

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
  std::uint32_t lane;  // the first of the 8 lanes that hold it
};

#if defined(__AVX512F__)
// The 8 times of a line in one register: the smallest by a reduction of packed
// minima, its first lane by an equality mask. (Halves by __builtin_shufflevector:
// GCC 12 warns of an undefined operand inside the intrinsics for them.)
[[gnu::always_inline]] inline LaneWinner lane_winner(__m512d line) {
  const __m256d m4 = _mm256_min_pd(__builtin_shufflevector(line, line, 0, 1, 2, 3),
                                   __builtin_shufflevector(line, line, 4, 5, 6, 7));
  const __m128d m2 = _mm_min_pd(__builtin_shufflevector(m4, m4, 0, 1), __builtin_shufflevector(m4, m4, 2, 3));
  const __m128d m1 = _mm_min_sd(m2, _mm_unpackhi_pd(m2, m2));
  const unsigned mask = _mm512_cmpeq_pd_mask(line, _mm512_set1_pd(_mm_cvtsd_f64(m1)));
  return {key_of(_mm_cvtsd_f64(m1)), static_cast<std::uint32_t>(std::countr_zero(mask))};
}
#endif

// The earliest of the 8 times at t (a 64-byte aligned line).
[[gnu::always_inline]] inline LaneWinner lane_winner(const double* t) {
#if defined(__AVX512F__)
  return lane_winner(_mm512_load_pd(t));
#elif defined(__SSE2__)
  // Three packed minima, then the first lane by an equality mask: the same
  // winner as the pairwise tournament below, in fewer instructions. (Loading
  // each pair as two 8-byte halves, which the 8-byte stores of a collision can
  // forward, measured no faster: 0.99x, 5 pairs at N = 10^6, t = 10^3.)
  const __m128d a = _mm_load_pd(t), c = _mm_load_pd(t + 2), e = _mm_load_pd(t + 4), g = _mm_load_pd(t + 6);
  const __m128d m2 = _mm_min_pd(_mm_min_pd(a, c), _mm_min_pd(e, g));
  const __m128d m1 = _mm_min_sd(m2, _mm_unpackhi_pd(m2, m2));
  const __m128d m = _mm_unpacklo_pd(m1, m1);
  const unsigned mask = static_cast<unsigned>(_mm_movemask_pd(_mm_cmpeq_pd(a, m))) |
                        static_cast<unsigned>(_mm_movemask_pd(_mm_cmpeq_pd(c, m))) << 2 |
                        static_cast<unsigned>(_mm_movemask_pd(_mm_cmpeq_pd(e, m))) << 4 |
                        static_cast<unsigned>(_mm_movemask_pd(_mm_cmpeq_pd(g, m))) << 6;
  return {key_of(_mm_cvtsd_f64(m1)), static_cast<std::uint32_t>(std::countr_zero(mask))};
#else
  TimeKey k0 = key_of(t[0]), k1 = key_of(t[1]), k2 = key_of(t[2]), k3 = key_of(t[3]);
  TimeKey k4 = key_of(t[4]), k5 = key_of(t[5]), k6 = key_of(t[6]), k7 = key_of(t[7]);
  std::uint32_t a0 = 0, a2 = 2, a4 = 4, a6 = 6;
  take_earlier(k0, a0, k1, 1);
  take_earlier(k2, a2, k3, 3);
  take_earlier(k4, a4, k5, 5);
  take_earlier(k6, a6, k7, 7);
  take_earlier(k0, a0, k2, a2);
  take_earlier(k4, a4, k6, a6);
  take_earlier(k0, a0, k4, a4);
  return {k0, a0};
#endif
}

#if defined(__AVX512F__)
// A collision's three new slot times (tp, +inf, tj for slots p, p + 1, p + 2)
// merged into the lines that hold them, in registers. o = p mod 8: the slots
// are lanes o .. o + 2 of line 0 and, past lane 7, the first lanes of line 1.
class ThreeTimes {
 public:
  ThreeTimes(std::uint32_t o, double tp, double never, double tj)
      : values_(spread(_mm_set_pd(never, tp), _mm_set1_pd(tj))),
        // Lane l takes value (l - o) mod 8: lanes o, o + 1, o + 2 of line 0 and
        // lanes o - 8, o - 7, o - 6 of line 1 take 0, 1, 2 (the permute reads 3 bits).
        index_(_mm512_sub_epi64(_mm512_setr_epi64(0, 1, 2, 3, 4, 5, 6, 7), _mm512_set1_epi64(o))),
        lanes_(0b111u << o) {}
  // Whether the three lie in one line.
  bool one_line() const { return lanes_ < 0x100; }
  // Line k (0 or 1) at t with its slots replaced.
  __m512d merged(const double* t, int k) const {
    const auto lanes = static_cast<__mmask8>(k == 0 ? lanes_ : lanes_ >> 8);
    return _mm512_mask_permutexvar_pd(_mm512_load_pd(t), lanes, index_, values_);
  }

 private:
  // (a0, a1, b0) in lanes 0, 1, 2 (the others unused).
  static __m512d spread(__m128d a, __m128d b) {
    const __m256d four = __builtin_shufflevector(a, b, 0, 1, 2, 3);
    return __builtin_shufflevector(four, four, 0, 1, 2, 3, 0, 1, 2, 3);
  }
  __m512d values_;
  __m512i index_;
  unsigned lanes_;  // bit l: lane l of line 0, bit 8 + l: lane l of line 1
};
#endif

}  // namespace shockgas::particles::detail
