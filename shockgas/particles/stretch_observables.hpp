#pragma once
// The observables of one sample in parts (private to particles/): each stretch
// of the chain (a domain of a window plan) measures its part when it reaches
// the sample time, while its bodies are in cache, and the parts are combined in
// chain order. No sweep over the whole state per sample, and a result that does
// not depend on which thread measured which stretch.
//
// Moments. A stretch sums M_s = sum m, P_s = sum m v and, in a second pass over
// its bodies, C_s = sum m (v - P_s / M_s)^2. Combined in stretch order
// (Chan, Golub & LeVeque 1979, the pairwise update of the sum of squares):
//   M = sum M_s,  P = sum P_s,  T = sum [C_s + M_s (P_s / M_s - P / M)^2] / M,
// the same temperature as chain_temperature's sum m (v - <v>)^2 / M, summed in
// another order (equal to rounding: about N eps relative).
//
// Clusters. The count is that of ClusterCounter (chain_observables.hpp) to the
// bit: every pair of chain neighbours joins or not by the same criteria on the
// same numbers, inside a stretch (ClusterScan) or across the cut between two
// (count_clusters), and every body is lone and light or not by the same pairs
// and MultiParticleRule: a stretch settles its bodies but its ends
// (lone_bodies.hpp), the cuts settle those, the closing pair (below) the two
// beside it. A pair whose wrapped positions drop is counted across the ring's
// wrap (gap w_right + L - w_left); the count stands when the ring has exactly
// one such drop (the seam) or none (then the pair that closes the chain order
// from body 0 is the wrapping one), and a line none. Where rounding left
// touching bodies out of order inside a stretch, the stretch also gives the part
// of its bodies sorted stably by x on each side of the seam (sorted_part), which
// stand in for it: the count of the whole state sorted stably (find_clusters on
// sorted_bodies), since a cut is a wide gap that rounding does not reorder. (Bodies
// at exactly equal positions on both sides of a rounding drop may be ordered
// otherwise than by the whole-state sort; they join the same neighbours unless
// their velocities differ across the criteria.)
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "shockgas/particles/cluster_finder.hpp"
#include "shockgas/particles/lone_bodies.hpp"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace shockgas::particles::detail {

// What a sample measures, as the recorder asks (clusters: count those `counted` counts).
struct SampleSpec {
  bool clusters = false;
  ClusterCriteria criteria;
  MultiParticleRule counted;
  double L = 0;  // ring length [length]; unused on a line
  bool ring = false;
};

// The clusters' part of a stretch: its pairs inside, and its ends for the cuts.
struct ClusterPart {
  std::size_t joined = 0;    // pairs inside that join
  std::size_t drops = 0;     // pairs inside whose wrapped positions drop
  double max_drop = 0;       // the largest drop w_left - w_right [length]
  int closing_counted = -1;  // the closing pair inside (right body of lower index): its join as counted
  int closing_wrapped = -1;  // ... and across the wrap; -1 when it is not inside
  double first_w = 0, first_v = 0, last_w = 0, last_v = 0;  // wrapped x and v of the ends
  std::size_t first_index = 0, last_index = 0;              // body indices of the ends
  LoneBodies lone;            // from the first body (or the closing pair's right one) to the last
  LoneBodies before_closing;  // with the closing pair inside: from the first body to its left one
};

// A body as a scan takes it: wrapped position, velocity, mass.
struct ScanBody {
  double w = 0, v = 0, m = 0;
};

// The pairs of bodies 0 .. n - 1 of a run, counted apart from its body 0: how
// many join, the first (0, 1) and the last (n - 2, n - 1), how many of bodies
// 1 .. n - 2 are lone and light, and whether body n - 1 is light
// (LoneBodies::add_run).
struct RunPairs {
  std::size_t joined = 0, lone = 0;
  bool first_joins = false, last_joins = false, last_light = false;
};

// Feeds the bodies of a stretch in chain order: their wrapped positions w,
// velocities and masses; closes: the body is the right one of the pair that
// closes the chain order from body 0 (its index below its left neighbour's).
class ClusterScan {
 public:
  explicit ClusterScan(const SampleSpec& spec)
      : criteria_(spec.criteria), counted_(spec.counted), L_(spec.ring ? spec.L : 0.0) {}
  void add(double w, double v, double m, std::size_t index, bool closes) {
    const bool light = !counted_.heavy(m);
    if (started_) [[likely]] {
      const bool drop = w < p_.last_w;
      const double gap = drop ? (w + L_) - p_.last_w : w - p_.last_w;
      const bool join = criteria_.joins(gap, v - p_.last_v);
      p_.joined += join;
      p_.drops += drop;
      if (drop) [[unlikely]]
        p_.max_drop = std::max(p_.max_drop, p_.last_w - w);
      if (closes) [[unlikely]] {  // settled across it by count_clusters
        p_.closing_counted = join, p_.closing_wrapped = criteria_.joins((w + L_) - p_.last_w, v - p_.last_v);
        p_.before_closing = p_.lone, p_.lone.start(light);
      } else {
        p_.lone.add(join, light);
      }
    } else {
      p_.first_w = w, p_.first_v = v, p_.first_index = index, started_ = true;
      p_.lone.start(light);
    }
    p_.last_w = w, p_.last_v = v, p_.last_index = index;
  }
  // add() for the n bodies of a run (n >= 1), w, v and m of each in chain
  // order, of which only the first may close; first_index, last_index: the
  // indices of its ends. The pairs inside without branches, two at a time (the
  // same numbers as add(): (w + 0) - w_left is w - w_left).
  void add_run(const double* w, const double* v, const double* m, std::size_t n, std::size_t first_index,
               std::size_t last_index, bool closes) {
    add(w[0], v[0], m[0], first_index, closes);
    if (n == 1) return;
    RunPairs r;
    std::size_t drops = 0, k = 1;
    auto pair = [&](std::size_t j, bool& drop) {
      drop = w[j] < w[j - 1];
      return criteria_.joins((w[j] + (drop ? L_ : 0.0)) - w[j - 1], v[j] - v[j - 1]);
    };
    bool drop = false;
    r.first_joins = pair(1, drop);
    bool left_joins = true;  // of body k - 1; body 0 is add()'s
#if defined(__SSE2__)
    const __m128d L = _mm_set1_pd(L_), max_gap = _mm_set1_pd(criteria_.max_gap);
    const __m128d max_dv = _mm_set1_pd(criteria_.max_dv), sign = _mm_set1_pd(-0.0);
    const __m128d heavy = _mm_set1_pd(counted_.heavy_mass());
    __m128i joined2 = _mm_setzero_si128(), drops2 = _mm_setzero_si128();  // minus the masks: counts
    __m128i held2 = _mm_setzero_si128();  // bodies k - 1, k joined on either side or heavy: minus the masks
    __m128d join_l = _mm_castsi128_pd(_mm_set1_epi64x(-1));  // pair k - 1 in the high half
    for (; k + 2 <= n; k += 2) {
      const __m128d wr = _mm_loadu_pd(w + k), wl = _mm_loadu_pd(w + k - 1);
      const __m128d drop2 = _mm_cmplt_pd(wr, wl);
      const __m128d gap = _mm_sub_pd(_mm_add_pd(wr, _mm_and_pd(drop2, L)), wl);
      const __m128d dv = _mm_andnot_pd(sign, _mm_sub_pd(_mm_loadu_pd(v + k), _mm_loadu_pd(v + k - 1)));
      const __m128d join = _mm_and_pd(_mm_cmplt_pd(gap, max_gap), _mm_cmplt_pd(dv, max_dv));
      const __m128d beside = _mm_or_pd(join, _mm_shuffle_pd(join_l, join, 1));  // pairs k - 1, k | k, k + 1
      const __m128d held = _mm_or_pd(beside, _mm_cmpgt_pd(_mm_loadu_pd(m + k - 1), heavy));
      joined2 = _mm_sub_epi64(joined2, _mm_castpd_si128(join));
      drops2 = _mm_sub_epi64(drops2, _mm_castpd_si128(drop2));
      held2 = _mm_sub_epi64(held2, _mm_castpd_si128(held));
      join_l = join;
    }
    alignas(16) std::array<std::uint64_t, 6> lanes;
    _mm_store_si128(reinterpret_cast<__m128i*>(lanes.data()), joined2);
    _mm_store_si128(reinterpret_cast<__m128i*>(lanes.data() + 2), drops2);
    _mm_store_si128(reinterpret_cast<__m128i*>(lanes.data() + 4), held2);
    r.joined = lanes[0] + lanes[1], drops = lanes[2] + lanes[3];
    r.lone = (k - 1) - (lanes[4] + lanes[5]);
    left_joins = (_mm_movemask_pd(join_l) & 2) != 0;
#endif
    for (; k < n; ++k) {
      const bool joins = pair(k, drop);
      r.joined += joins, drops += drop;
      r.lone += !left_joins & !joins & !counted_.heavy(m[k - 1]);
      left_joins = joins;
    }
    r.last_joins = left_joins, r.last_light = !counted_.heavy(m[n - 1]);
    p_.drops += drops;
    if (drops > 0) [[unlikely]]
      for (std::size_t j = 1; j < n; ++j) p_.max_drop = std::max(p_.max_drop, w[j - 1] - w[j]);
    add_clean(r, w[n - 1], v[n - 1], last_index);
  }
  // After add() of a run's first body: the rest of the run, whose pairs do not
  // drop, counted in r; w, v and index of its last body.
  void add_clean(const RunPairs& r, double w, double v, std::size_t index) {
    p_.joined += r.joined;
    p_.lone.add_run(r.first_joins, r.lone, r.last_joins, r.last_light);
    p_.last_w = w, p_.last_v = v, p_.last_index = index;
  }
  const ClusterPart& part() const { return p_; }
  const ClusterCriteria& criteria() const { return criteria_; }
  const MultiParticleRule& counted() const { return counted_; }

 private:
  ClusterCriteria criteria_;
  MultiParticleRule counted_;
  double L_;
  bool started_ = false;
  ClusterPart p_;
};

// Whether rounding left a stretch's part out of order: a drop that is not the
// ring's seam (on a ring one drop of more than L / 2 is the seam).
bool out_of_order(const ClusterPart& part, const SampleSpec& spec);

// The part of a stretch's bodies (in chain order) sorted stably by w on each
// side of the seam (the largest drop, on a ring, if it exceeds L / 2).
ClusterPart sorted_part(std::vector<ScanBody> bodies, std::size_t first_index, std::size_t last_index,
                        const SampleSpec& spec);

// One stretch at a sample time.
struct StretchPart {
  std::array<std::uint64_t, 3> count{};       // collisions by kind since the stretch's previous part
  double dissipated = 0;                      // since then [mass length^2/time^2]
  double mass = 0, momentum = 0, spread = 0;  // M_s, P_s, C_s
  std::size_t bodies = 0;
  ClusterPart clusters;
  bool taken = false;  // the stretch reached the sample time
};

// Moments of the whole chain from its stretches in chain order.
struct SampleMoments {
  double mass = 0, momentum = 0, T = 0;
  std::size_t bodies = 0;
};
SampleMoments combine_moments(const StretchPart* parts, std::size_t count, std::size_t stride);

// The number of clusters counted (spec.counted) from the stretches' parts in
// chain order (parts[k] the k-th stretch's), and whether the wrapped positions
// were in order (else the count takes each pair as it stands).
struct ClusterCount {
  std::size_t count = 0;
  bool ordered = true;
};
ClusterCount count_clusters(const std::vector<const ClusterPart*>& parts, std::size_t bodies,
                            const SampleSpec& spec);

}  // namespace shockgas::particles::detail
