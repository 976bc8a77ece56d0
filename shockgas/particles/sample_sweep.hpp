#pragma once
// One pass over a run of equal-mass bodies at a sample time (private to
// particles/): the velocity sums of the moments' first pass and the cluster
// scan's pairs, from one load of each body (DomainSampler, equal masses). The
// general path computes the same in three loops over buffers (positions at t,
// PeriodWrap::wrap_all, ClusterScan::add_run) and a separate pass for the sums;
// this one keeps everything in registers, so a sample costs one stream over the
// bodies and a few operations per body: four bodies a step (AVX2), or eight
// (AVX-512) and the last four.
//
// The numbers are those of the general path, operation for operation:
//  * position x + v (t - t_body) (Body::at), on a ring wrapped as wrap_all does
//    for a run inside the period of its first body, x - L k (its clamp to 0
//    outside [0, L) is checked, once per period, not to act there; see sweep_run);
//  * pairs as add_run: gap w - w_left, join when gap < max_gap and
//    |v - v_left| < max_dv (ClusterCriteria::joins); bodies that join neither
//    neighbour from the same masks (RunPairs);
//  * velocity sums in four lanes in the order of DomainSampler's moments: body k
//    of a range into lane k mod 4, the last (size mod 4) bodies of the range
//    into lane 0, one after the other.
// A run for which that is not the whole story goes the general way for its
// clusters (sweep_run returns false; its sums are added either way): on a ring a
// body outside the first one's period (wrap_all then wraps body by body), and a
// pair whose positions drop (the ring's seam, or rounding: add_run then adds L
// to the gap and keeps the largest drop). Without a drop add_run's gap
// (w + 0) - w_left is w - w_left, up to the sign of a zero gap, which no
// comparison sees.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>

#include "shockgas/particles/ring_wrap.hpp"
#include "shockgas/particles/stretch_observables.hpp"

#if defined(__AVX2__)
#include <immintrin.h>
#elif defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace shockgas::particles::detail {

#if defined(__SSE2__)

// The velocity sums of the moments' first pass: lane k holds its bodies' sum.
using LaneSums = double[4];

// How a run's positions become the scan's: as they are (a line), in the ring's
// first period (x - 0 is x), or shifted by the period's L k.
enum class RunWrap { none, first, shifted };

// What the blocks of four bodies leave to the rest of a run: the next body,
// the joins counted, the bodies from 1 on that join neither neighbour (body
// next - 1 not yet: its right pair is the rest's), whether the last pair joins
// (true before any: body 0's left pair is not the run's), whether a pair
// dropped (or, shifted, a position left the period), and the last body's w and v.
struct BlockSweep {
  std::size_t next = 1, joins = 0, unjoined = 0;
  bool last_joins = true, off = false;
  double w_l = 0, v_l = 0;
};

// The double below hi where it is needed (a library call per run otherwise).
inline double below(double hi, bool needed) {
  return needed ? std::nextafter(hi, -std::numeric_limits<double>::infinity()) : hi;
}

// Bodies 1 .. 4 m of a run (x, v, t of body k at q + 3 k; 4 m + 1 <= n), four at
// a time: body k into lane k mod 4 of s, the pairs (k - 1, k) counted. w0, v0:
// body 0's. x < lo is x - lo < 0 and x >= hi is pred(hi) - x < 0 (for doubles,
// a - b has the sign of the difference; +0 when equal). A gap below 0 is a drop
// (w < w_left); so is a zero gap from -0 - +0, a false alarm that only sends
// the run the general way.
#if defined(__AVX2__)
// Where the blocks of eight (sweep_eights) leave the blocks of four: the next
// body, body k - 1's w and v, whether pair (k - 2, k - 1) joins, the counts,
// the velocity sums in the lanes of bodies 1, 2, 3, 4 mod 4 and the sign bits
// of everything `off` watches, or-ed.
struct EightsSweep {
  std::size_t next;
  double w_l, v_l;
  bool last_joins;
  std::uint64_t joins = 0, held = 0;
  __m256d sums, off;
};

#if defined(__AVX512F__) && defined(__AVX512DQ__)
// The halves of a vector (the masked extraction: g++ 12's plain one, and the
// cast through it, read an undefined vector, which -Wmaybe-uninitialized flags).
inline __m256d low_half(__m512d x) { return _mm512_maskz_extractf64x4_pd(0xF, x, 0); }
inline __m256d high_half(__m512d x) { return _mm512_maskz_extractf64x4_pd(0xF, x, 1); }

// Bodies k .. k + 7 stored as x, v, t (q = &body[k].x): each field from the
// three loads of their 24 doubles by two permutations, the first five or six
// bodies from the first two loads, the rest from the third.
struct EightBodies {
  __m512d x, v, t;
};
inline EightBodies load_eight(const double* q) {
  const __m512d a = _mm512_loadu_pd(q), b = _mm512_loadu_pd(q + 8), e = _mm512_loadu_pd(q + 16);
  auto field = [&](__m512i from_ab, __m512i from_e) {
    return _mm512_permutex2var_pd(_mm512_permutex2var_pd(a, from_ab, b), from_e, e);
  };
  return {field(_mm512_setr_epi64(0, 3, 6, 9, 12, 15, 0, 0), _mm512_setr_epi64(0, 1, 2, 3, 4, 5, 10, 13)),
          field(_mm512_setr_epi64(1, 4, 7, 10, 13, 0, 0, 0), _mm512_setr_epi64(0, 1, 2, 3, 4, 8, 11, 14)),
          field(_mm512_setr_epi64(2, 5, 8, 11, 14, 0, 0, 0), _mm512_setr_epi64(0, 1, 2, 3, 4, 9, 12, 15))};
}

// Bodies 1 .. 8 m of a run, eight at a time: in each lane the operations of
// sweep_blocks' lanes (the same positions, gaps and joins), the velocity
// sums of bodies k .. k + 3, then k + 4 .. k + 7, into the four lanes (the
// order of two blocks of four), the counts from the join masks.
template <bool Shifted>
EightsSweep sweep_eights(const double* q, std::size_t n, double t, const ClusterCriteria& c,
                         const PeriodWrap::Period& period, EightsSweep r) {
  const __m512d at = _mm512_set1_pd(t), max_gap = _mm512_set1_pd(c.max_gap);
  const __m512d max_dv = _mm512_set1_pd(c.max_dv), sign = _mm512_set1_pd(-0.0);
  const __m512d shift = _mm512_set1_pd(period.shift), lo = _mm512_set1_pd(period.lo);
  const __m512d below_hi = _mm512_set1_pd(below(period.hi, Shifted));
  const __m512i after =
      _mm512_setr_epi64(15, 0, 1, 2, 3, 4, 5, 6);  // body k - 1 (top of before), then k .. k + 6
  __m512d w_prev = _mm512_set1_pd(r.w_l), v_prev = _mm512_set1_pd(r.v_l), off = _mm512_setzero_pd();
  unsigned join_prev = r.last_joins ? 1u : 0u;
  std::size_t k = r.next;
  for (; k + 8 <= n; k += 8) {
    const auto [x, v, tb] = load_eight(q + 3 * k);
    const __m512d pos = _mm512_add_pd(x, _mm512_mul_pd(v, _mm512_sub_pd(at, tb)));  // Body::at
    __m512d w = pos;
    if constexpr (Shifted) {
      off = _mm512_or_pd(off, _mm512_or_pd(_mm512_sub_pd(pos, lo), _mm512_sub_pd(below_hi, pos)));
      w = _mm512_sub_pd(pos, shift);
    }
    r.sums = _mm256_add_pd(r.sums, low_half(v));
    r.sums = _mm256_add_pd(r.sums, high_half(v));
    const __m512d gap = _mm512_sub_pd(w, _mm512_permutex2var_pd(w, after, w_prev));
    const __m512d dv = _mm512_andnot_pd(sign, _mm512_sub_pd(v, _mm512_permutex2var_pd(v, after, v_prev)));
    off = _mm512_or_pd(off, gap);
    const unsigned join =
        _mm512_cmp_pd_mask(gap, max_gap, _CMP_LT_OQ) & _mm512_cmp_pd_mask(dv, max_dv, _CMP_LT_OQ);
    r.joins += static_cast<std::uint64_t>(__builtin_popcount(join));
    r.held += static_cast<std::uint64_t>(__builtin_popcount((join | (join << 1) | join_prev) & 0xFFu));
    join_prev = join >> 7;
    w_prev = w, v_prev = v;
  }
  if (k == r.next) return r;
  alignas(64) double last_w[8], last_v[8];
  _mm512_store_pd(last_w, w_prev), _mm512_store_pd(last_v, v_prev);
  r.off = _mm256_or_pd(r.off, _mm256_or_pd(low_half(off), high_half(off)));
  r.next = k, r.w_l = last_w[7], r.v_l = last_v[7], r.last_joins = join_prev != 0;
  return r;
}
#endif

template <bool Shifted>
BlockSweep sweep_blocks(const double* q, std::size_t n, double t, const ClusterCriteria& c,
                        const PeriodWrap::Period& period, double w0, double v0, LaneSums& s) {
  const __m256d at = _mm256_set1_pd(t), max_gap = _mm256_set1_pd(c.max_gap);
  const __m256d max_dv = _mm256_set1_pd(c.max_dv), sign = _mm256_set1_pd(-0.0);
  const __m256d shift = _mm256_set1_pd(period.shift), lo = _mm256_set1_pd(period.lo);
  const __m256d below_hi = _mm256_set1_pd(below(period.hi, Shifted));
  // lanes of bodies 1, 2, 3, 4 mod 4
  EightsSweep eights{1, w0, v0, true, 0, 0, _mm256_set_pd(s[0], s[3], s[2], s[1]), _mm256_setzero_pd()};
#if defined(__AVX512F__) && defined(__AVX512DQ__)
  eights = sweep_eights<Shifted>(q, n, t, c, period, eights);
#endif
  __m256d sums = eights.sums, off = eights.off;
  __m256d w_prev = _mm256_set1_pd(eights.w_l), v_prev = _mm256_set1_pd(eights.v_l);
  __m256i joined = _mm256_setzero_si256();  // minus the join masks: counts
  __m256i held = _mm256_setzero_si256();    // bodies k - 1 .. k + 2 joined on either side: minus the masks
  __m256d join_prev =
      _mm256_castsi256_pd(_mm256_set1_epi64x(eights.last_joins ? -1 : 0));  // pair k - 1 in the top lane
  // Bodies k - 1 .. k + 2 from body k - 1 (the last of before) and k .. k + 3 (now).
  auto shifted_in = [](__m256d before, __m256d now) {
    return _mm256_shuffle_pd(_mm256_permute2f128_pd(before, now, 0x21), now, 0b0101);
  };
  std::size_t k = eights.next;
  for (; k + 4 <= n; k += 4) {  // k = 1 mod 4; bodies k, k + 1 | k + 2, k + 3 in the halves
    const __m256d a = _mm256_loadu2_m128d(q + 3 * k + 6, q + 3 * k);       // x v | x v
    const __m256d b = _mm256_loadu2_m128d(q + 3 * k + 8, q + 3 * k + 2);   // t x | t x
    const __m256d e = _mm256_loadu2_m128d(q + 3 * k + 10, q + 3 * k + 4);  // v t | v t
    const __m256d x = _mm256_shuffle_pd(a, b, 0b1010), v = _mm256_shuffle_pd(a, e, 0b0101);
    const __m256d tb = _mm256_shuffle_pd(b, e, 0b1010);
    const __m256d pos = _mm256_add_pd(x, _mm256_mul_pd(v, _mm256_sub_pd(at, tb)));  // Body::at
    __m256d w = pos;
    if constexpr (Shifted) {
      off = _mm256_or_pd(off, _mm256_or_pd(_mm256_sub_pd(pos, lo), _mm256_sub_pd(below_hi, pos)));
      w = _mm256_sub_pd(pos, shift);
    }
    sums = _mm256_add_pd(sums, v);
    const __m256d gap = _mm256_sub_pd(w, shifted_in(w_prev, w));
    const __m256d dv = _mm256_andnot_pd(sign, _mm256_sub_pd(v, shifted_in(v_prev, v)));
    off = _mm256_or_pd(off, gap);
    const __m256d join =
        _mm256_and_pd(_mm256_cmp_pd(gap, max_gap, _CMP_LT_OQ), _mm256_cmp_pd(dv, max_dv, _CMP_LT_OQ));
    joined = _mm256_sub_epi64(joined, _mm256_castpd_si256(join));
    held = _mm256_sub_epi64(held, _mm256_castpd_si256(_mm256_or_pd(join, shifted_in(join_prev, join))));
    w_prev = w, v_prev = v, join_prev = join;
  }
  alignas(32) double lane[4];
  _mm256_store_pd(lane, sums);
  s[1] = lane[0], s[2] = lane[1], s[3] = lane[2], s[0] = lane[3];
  alignas(32) std::uint64_t count[4], held_count[4];
  _mm256_store_si256(reinterpret_cast<__m256i*>(count), joined);
  _mm256_store_si256(reinterpret_cast<__m256i*>(held_count), held);
  alignas(32) double last_w[4], last_v[4];
  _mm256_store_pd(last_w, w_prev), _mm256_store_pd(last_v, v_prev);
  const std::size_t unjoined =
      (k - 1) - (eights.held + held_count[0] + held_count[1] + held_count[2] + held_count[3]);
  return {k,
          eights.joins + count[0] + count[1] + count[2] + count[3],
          unjoined,
          (_mm256_movemask_pd(join_prev) & 8) != 0,
          _mm256_movemask_pd(off) != 0,
          last_w[3],
          last_v[3]};
}
#else
template <bool Shifted>
BlockSweep sweep_blocks(const double* q, std::size_t n, double t, const ClusterCriteria& c,
                        const PeriodWrap::Period& period, double w0, double v0, LaneSums& s) {
  const __m128d at = _mm_set1_pd(t), max_gap = _mm_set1_pd(c.max_gap), max_dv = _mm_set1_pd(c.max_dv);
  const __m128d sign = _mm_set1_pd(-0.0), shift = _mm_set1_pd(period.shift), lo = _mm_set1_pd(period.lo);
  const __m128d below_hi = _mm_set1_pd(below(period.hi, Shifted));
  __m128d s12 = _mm_set_pd(s[2], s[1]), s30 = _mm_set_pd(s[0], s[3]);  // lanes of bodies 1, 2 and 3, 4 mod 4
  __m128d w_prev = _mm_set1_pd(w0), v_prev = _mm_set1_pd(v0);          // body k - 1 in the high half
  __m128d off = _mm_setzero_pd();
  __m128i joined = _mm_setzero_si128();  // minus the join masks: counts
  __m128i held = _mm_setzero_si128();    // bodies k - 1, k joined on either side: minus the masks
  __m128d join_prev = _mm_castsi128_pd(_mm_set1_epi64x(-1));  // pair k - 1 in the high half
  // Bodies k, k + 1: positions at t (wrapped) and velocities.
  auto load = [&](std::size_t k, __m128d& w, __m128d& v) {
    const __m128d a = _mm_loadu_pd(q + 3 * k), b = _mm_loadu_pd(q + 3 * k + 2);
    const __m128d e = _mm_loadu_pd(q + 3 * k + 4);
    const __m128d x = _mm_shuffle_pd(a, b, 2);                             // x_k, x_k+1
    v = _mm_shuffle_pd(a, e, 1);                                           // v_k, v_k+1
    const __m128d tb = _mm_shuffle_pd(b, e, 2);                            // t_k, t_k+1
    const __m128d pos = _mm_add_pd(x, _mm_mul_pd(v, _mm_sub_pd(at, tb)));  // Body::at
    w = pos;
    if constexpr (Shifted) {
      off = _mm_or_pd(off, _mm_or_pd(_mm_sub_pd(pos, lo), _mm_sub_pd(below_hi, pos)));
      w = _mm_sub_pd(pos, shift);
    }
  };
  // The pairs (k - 1, k) and (k, k + 1) given body k - 1 (high halves of w_l, v_l) and k, k + 1.
  auto pairs = [&](__m128d w_l, __m128d v_l, __m128d w, __m128d v) {
    const __m128d gap = _mm_sub_pd(w, _mm_shuffle_pd(w_l, w, 1));
    const __m128d dv = _mm_andnot_pd(sign, _mm_sub_pd(v, _mm_shuffle_pd(v_l, v, 1)));
    off = _mm_or_pd(off, gap);
    const __m128d join = _mm_and_pd(_mm_cmplt_pd(gap, max_gap), _mm_cmplt_pd(dv, max_dv));
    joined = _mm_sub_epi64(joined, _mm_castpd_si128(join));
    held = _mm_sub_epi64(held, _mm_castpd_si128(_mm_or_pd(join, _mm_shuffle_pd(join_prev, join, 1))));
    join_prev = join;
  };
  std::size_t k = 1;
  for (; k + 4 <= n; k += 4) {  // k = 1 mod 4
    __m128d w1, v1, w2, v2;
    load(k, w1, v1);
    load(k + 2, w2, v2);
    s12 = _mm_add_pd(s12, v1);
    s30 = _mm_add_pd(s30, v2);
    pairs(w_prev, v_prev, w1, v1);
    pairs(w1, v1, w2, v2);
    w_prev = w2, v_prev = v2;
  }
  _mm_storel_pd(&s[1], s12), _mm_storeh_pd(&s[2], s12);
  _mm_storel_pd(&s[3], s30), _mm_storeh_pd(&s[0], s30);
  alignas(16) std::uint64_t count[2], held_count[2];
  _mm_store_si128(reinterpret_cast<__m128i*>(count), joined);
  _mm_store_si128(reinterpret_cast<__m128i*>(held_count), held);
  return {k,
          count[0] + count[1],
          (k - 1) - (held_count[0] + held_count[1]),
          (_mm_movemask_pd(join_prev) & 2) != 0,
          _mm_movemask_pd(off) != 0,
          _mm_cvtsd_f64(_mm_unpackhi_pd(w_prev, w_prev)),
          _mm_cvtsd_f64(_mm_unpackhi_pd(v_prev, v_prev))};
}
#endif

// sweep_run for one RunWrap. On a ring: the period of x0, where wrap_all wraps x
// as x - shift, clamped to 0 outside [0, L); the caller checked that no x in
// [lo, hi) is clamped. Positions must lie in [lo, hi): with `shifted` each one
// is checked; in the first period x0 and the last are, and no drop means none
// in between lies outside them (w = x there).
template <RunWrap Wrap, class Body>
bool sweep_run_as(const Body* p, std::size_t n, double t, double m, std::size_t index, bool closes,
                  LaneSums& s, ClusterScan& scan, const PeriodWrap::Period& period) {
  static_assert(sizeof(Body) == 3 * sizeof(double), "Body is x, v, t");
  constexpr bool shifted = Wrap == RunWrap::shifted;
  const ClusterCriteria& c = scan.criteria();
  const double x0 = p[0].at(t), v0 = p[0].v;
  const double w0 = shifted ? x0 - period.shift : x0;
  const std::size_t whole = n & ~std::size_t{3};  // bodies 0 .. whole - 1 go to lane k mod 4
  s[0] += v0;
  BlockSweep r = sweep_blocks<shifted>(&p[0].x, n, t, c, period, w0, v0, s);
  for (std::size_t k = r.next; k < n; ++k) {
    const double x = p[k].at(t), v = p[k].v;
    s[k < whole ? k % 4 : 0] += v;
    if constexpr (shifted) r.off |= !(x >= period.lo && x < period.hi);
    const double w = shifted ? x - period.shift : x;
    r.off |= w < r.w_l;
    const bool joins = c.joins(w - r.w_l, v - r.v_l);
    r.joins += joins, r.unjoined += !r.last_joins & !joins, r.last_joins = joins;
    r.w_l = w, r.v_l = v;
  }
  if constexpr (Wrap == RunWrap::first) r.off |= !(x0 >= period.lo && r.w_l < period.hi);
  if (r.off) return false;
  scan.add(w0, v0, m, index, closes);
  if (n == 1) return true;
  // The pair (0, 1) once more, as the blocks took it (no drop: w - w_left).
  const double x1 = p[1].at(t);
  const bool first_joins = c.joins((shifted ? x1 - period.shift : x1) - w0, p[1].v - v0);
  const bool light = !scan.counted().heavy(m);
  scan.add_clean({r.joins, light ? r.unjoined : 0, first_joins, r.last_joins, light}, r.w_l, r.v_l,
                 index + n - 1);
  return true;
}

// Bodies p[0 .. n) of mass m (n >= 1; n a multiple of 4 unless the run ends its
// range), index: that of p[0]; closes: p[0] closes the chain order
// (ClusterScan::add). Adds the velocities to s; feeds the bodies to scan unless
// it returns false.
template <bool Ring, class Body>
bool sweep_run(const Body* p, std::size_t n, double t, double m, std::size_t index, bool closes, LaneSums& s,
               ClusterScan& scan, PeriodWrap& wrap) {
  if constexpr (!Ring) {
    return sweep_run_as<RunWrap::none>(p, n, t, m, index, closes, s, scan, {});
  } else {
    // x - shift is monotone in x: when lo - shift >= 0 and hi - shift < L no x
    // in [lo, hi) is clamped. In the first period (shift 0, lo > 0), x - shift
    // is x.
    const PeriodWrap::Period period = wrap.period_of(p[0].at(t));
    if (period.lo - period.shift >= 0 && period.hi - period.shift < period.L) {
      if (period.shift == 0) return sweep_run_as<RunWrap::first>(p, n, t, m, index, closes, s, scan, period);
      return sweep_run_as<RunWrap::shifted>(p, n, t, m, index, closes, s, scan, period);
    }
    for (std::size_t k = 0; k < n; ++k) s[k < (n & ~std::size_t{3}) ? k % 4 : 0] += p[k].v;
    return false;
  }
}

#endif

}  // namespace shockgas::particles::detail
