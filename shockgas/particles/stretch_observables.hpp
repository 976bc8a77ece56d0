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
// (count_clusters). A pair whose wrapped positions drop is counted across the
// ring's wrap (gap w_right + L - w_left); the count stands when the ring has
// exactly one such drop (the seam) or none (then the pair that closes the chain
// order from body 0 is the wrapping one), and a line none. Where rounding left
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
#include <utility>
#include <vector>

#include "shockgas/particles/cluster_finder.hpp"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace shockgas::particles::detail {

// What a sample measures, as the recorder asks (clusters: count them).
struct SampleSpec {
  bool clusters = false;
  ClusterCriteria criteria;
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
};

// Feeds the bodies of a stretch in chain order: their wrapped positions w and
// velocities; closes: the body is the right one of the pair that closes the
// chain order from body 0 (its index below its left neighbour's).
class ClusterScan {
 public:
  explicit ClusterScan(const SampleSpec& spec) : criteria_(spec.criteria), L_(spec.ring ? spec.L : 0.0) {}
  void add(double w, double v, std::size_t index, bool closes) {
    if (started_) [[likely]] {
      const bool drop = w < p_.last_w;
      const double gap = drop ? (w + L_) - p_.last_w : w - p_.last_w;
      const bool join = criteria_.joins(gap, v - p_.last_v);
      p_.joined += join;
      p_.drops += drop;
      if (drop) [[unlikely]]
        p_.max_drop = std::max(p_.max_drop, p_.last_w - w);
      if (closes) [[unlikely]]
        p_.closing_counted = join, p_.closing_wrapped = criteria_.joins((w + L_) - p_.last_w, v - p_.last_v);
    } else {
      p_.first_w = w, p_.first_v = v, p_.first_index = index, started_ = true;
    }
    p_.last_w = w, p_.last_v = v, p_.last_index = index;
  }
  // add() for n consecutive bodies of indices index .. index + n - 1 (n >= 1),
  // of which only the first may close: the pairs inside without branches, two
  // at a time (the same numbers as add(): (w + 0) - w_left is w - w_left).
  void add_run(const double* w, const double* v, std::size_t n, std::size_t index, bool closes) {
    add(w[0], v[0], index, closes);
    std::size_t joined = 0, drops = 0, k = 1;
#if defined(__SSE2__)
    const __m128d L = _mm_set1_pd(L_), max_gap = _mm_set1_pd(criteria_.max_gap);
    const __m128d max_dv = _mm_set1_pd(criteria_.max_dv), sign = _mm_set1_pd(-0.0);
    __m128i joined2 = _mm_setzero_si128(), drops2 = _mm_setzero_si128();  // minus the masks: counts
    for (; k + 2 <= n; k += 2) {
      const __m128d wr = _mm_loadu_pd(w + k), wl = _mm_loadu_pd(w + k - 1);
      const __m128d drop = _mm_cmplt_pd(wr, wl);
      const __m128d gap = _mm_sub_pd(_mm_add_pd(wr, _mm_and_pd(drop, L)), wl);
      const __m128d dv = _mm_andnot_pd(sign, _mm_sub_pd(_mm_loadu_pd(v + k), _mm_loadu_pd(v + k - 1)));
      const __m128d join = _mm_and_pd(_mm_cmplt_pd(gap, max_gap), _mm_cmplt_pd(dv, max_dv));
      joined2 = _mm_sub_epi64(joined2, _mm_castpd_si128(join));
      drops2 = _mm_sub_epi64(drops2, _mm_castpd_si128(drop));
    }
    alignas(16) std::array<std::uint64_t, 4> lanes;
    _mm_store_si128(reinterpret_cast<__m128i*>(lanes.data()), joined2);
    _mm_store_si128(reinterpret_cast<__m128i*>(lanes.data() + 2), drops2);
    joined = lanes[0] + lanes[1], drops = lanes[2] + lanes[3];
#endif
    for (; k < n; ++k) {
      const bool drop = w[k] < w[k - 1];
      joined += criteria_.joins((w[k] + (drop ? L_ : 0.0)) - w[k - 1], v[k] - v[k - 1]);
      drops += drop;
    }
    p_.joined += joined, p_.drops += drops;
    if (drops > 0) [[unlikely]]
      for (std::size_t j = 1; j < n; ++j) p_.max_drop = std::max(p_.max_drop, w[j - 1] - w[j]);
    p_.last_w = w[n - 1], p_.last_v = v[n - 1], p_.last_index = index + n - 1;
  }
  // After add() of a run's first body: the rest of the run, whose pairs do not
  // drop, `joined` of them join; w, v and index of its last body.
  void add_clean(std::size_t joined, double w, double v, std::size_t index) {
    p_.joined += joined;
    p_.last_w = w, p_.last_v = v, p_.last_index = index;
  }
  const ClusterPart& part() const { return p_; }
  const ClusterCriteria& criteria() const { return criteria_; }

 private:
  ClusterCriteria criteria_;
  double L_;
  bool started_ = false;
  ClusterPart p_;
};

// Whether rounding left a stretch's part out of order: a drop that is not the
// ring's seam (on a ring one drop of more than L / 2 is the seam).
bool out_of_order(const ClusterPart& part, const SampleSpec& spec);

// The part of a stretch's bodies (w, v in chain order) sorted stably by w on each
// side of the seam (the largest drop, on a ring, if it exceeds L / 2).
ClusterPart sorted_part(std::vector<std::pair<double, double>> wv, std::size_t first_index,
                        std::size_t last_index, const SampleSpec& spec);

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

// The number of clusters from the stretches' parts in chain order (parts[k] the
// k-th stretch's), and whether the wrapped positions were in order (else the
// count takes each pair as it stands).
struct ClusterCount {
  std::size_t count = 0;
  bool ordered = true;
};
ClusterCount count_clusters(const std::vector<const ClusterPart*>& parts, std::size_t bodies,
                            const SampleSpec& spec);

}  // namespace shockgas::particles::detail
