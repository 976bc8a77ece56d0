#pragma once
// A domain's part of a sample (private to particles/): when a domain of a window
// plan reaches a sample time, its bodies (in cache: it just ran) are measured at
// that time as stretch_observables.hpp says. Used by WindowScheduler, which
// combines the parts of all domains in domain order.
#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <optional>
#include <utility>
#include <vector>

#include "shockgas/particles/event_engine.hpp"
#include "shockgas/particles/ring_wrap.hpp"
#include "shockgas/particles/sample_sweep.hpp"
#include "shockgas/particles/stretch_observables.hpp"
#include "shockgas/particles/window_domain.hpp"

namespace shockgas::particles::detail {

template <bool Linked>
class DomainSampler {
 public:
  using Engine = EventEngine<Linked>;
  explicit DomainSampler(const Engine& e) : e_(e) {}

  // The part of domain d at time t (>= the time of its last collision) as spec
  // says, with the collisions and dissipation since its previous part (taken
  // out of d). Sets *sorted when rounding left its bodies out of order (see
  // sorted_part).
  StretchPart take(Domain& d, double t, const SampleSpec& spec, std::optional<ClusterPart>& sorted) const {
    StretchPart p;
    p.count = d.count, p.dissipated = d.dissipated;
    d.count = {}, d.dissipated = 0;
    if (spec.clusters) {
      ClusterScan scan(spec);
      PeriodWrap wrap(spec.L);
      if constexpr (Linked) {
        scan_linked(d, t, spec.ring, p, scan, wrap);
      } else {
        sweep_equal(d, t, spec.ring, p, scan, wrap);
      }
      p.clusters = scan.part();
      if (out_of_order(p.clusters, spec)) sorted = sorted_of(d, t, spec, p.clusters);
    } else if constexpr (Linked) {
      moments_linked(d, p);
    } else {
      moments_equal(d, p);
    }
    p.taken = true;
    return p;
  }

 private:
  // f(i) for the bodies head .. tail of d in chain order.
  template <class F>
  void for_each(const Domain& d, F&& f) const {
    if constexpr (Linked) {
      for (std::size_t i = d.head;; i = e_.right(i)) {
        f(i);
        if (i == d.tail) break;
      }
    } else {
      for_ranges(d, [&](std::size_t lo, std::size_t hi) {
        for (std::size_t i = lo; i < hi; ++i) f(i);
      });
    }
  }
  // Mass, momentum and spread, each body its own mass; also(i) for each body
  // in the spread's pass.
  template <class Also>
  void moments_linked(const Domain& d, StretchPart& p, Also&& also) const {
    for_each(d, [&](std::size_t i) {
      p.mass += e_.mass_[i], p.momentum += e_.mass_[i] * e_.body_[i].v;
      ++p.bodies;
    });
    const double mean = p.momentum / p.mass;
    double spread = 0;  // in a register: also(i) stores doubles, which could be p's
    for_each(d, [&](std::size_t i) {
      const double dv = e_.body_[i].v - mean;
      spread += e_.mass_[i] * dv * dv;
      also(i);
    });
    p.spread = spread;
  }
  void moments_linked(const Domain& d, StretchPart& p) const {
    moments_linked(d, p, [](std::size_t) {});
  }
  // Equal masses m: M = k m, P = m sum v, C = m sum (v - mean)^2, each sum in
  // four lanes (the additions of one lane wait on each other; four overlap):
  // body i of a range lo .. hi in lane (i - lo) mod 4, the last (hi - lo) mod 4
  // in lane 0.
  void moments_equal(const Domain& d, StretchPart& p) const {
    const typename Engine::Body* body = e_.body_.data();
    double s[4] = {0, 0, 0, 0};
    for_ranges(d, [&](std::size_t lo, std::size_t hi) {
      std::size_t i = lo;
      for (; i + 4 <= hi; i += 4)
        s[0] += body[i].v, s[1] += body[i + 1].v, s[2] += body[i + 2].v, s[3] += body[i + 3].v;
      for (; i < hi; ++i) s[0] += body[i].v;
      p.bodies += hi - lo;
    });
    spread_equal(d, s, p);
  }
  // The moments from the lane sums of v (p.bodies counted), with the second pass.
  void spread_equal(const Domain& d, const double (&s)[4], StretchPart& p) const {
    const typename Engine::Body* body = e_.body_.data();
    const double m = e_.m0_;
    p.mass = static_cast<double>(p.bodies) * m;
    p.momentum = m * ((s[0] + s[1]) + (s[2] + s[3]));
    const double mean = p.momentum / p.mass;
    double s0 = 0, s1 = 0, s2 = 0, s3 = 0;
    auto sq = [&](std::size_t i) { return (body[i].v - mean) * (body[i].v - mean); };
    for_ranges(d, [&](std::size_t lo, std::size_t hi) {
      std::size_t i = lo;
#if defined(__AVX512F__) && defined(__AVX512DQ__)
      // Eight at a time: lanes 0 .. 3 take bodies i .. i + 3, then i + 4 .. i + 7
      // (the order of two steps of four), the same operations.
      static_assert(sizeof(typename Engine::Body) == 3 * sizeof(double), "Body is x, v, t");
      const __m512d mu8 = _mm512_set1_pd(mean);
      __m256d s0123 = _mm256_set_pd(s3, s2, s1, s0);
      for (; i + 8 <= hi; i += 8) {
        const __m512d dv = _mm512_sub_pd(load_eight(&body[i].x).v, mu8);
        const __m512d sq8 = _mm512_mul_pd(dv, dv);
        s0123 = _mm256_add_pd(_mm256_add_pd(s0123, low_half(sq8)), high_half(sq8));
      }
      alignas(32) double lane[4];
      _mm256_store_pd(lane, s0123);
      s0 = lane[0], s1 = lane[1], s2 = lane[2], s3 = lane[3];
#endif
#if defined(__SSE2__)
      // Lanes 0, 1 and 2, 3 two at a time: the same operations.
      const __m128d mu = _mm_set1_pd(mean);
      __m128d s01 = _mm_set_pd(s1, s0), s23 = _mm_set_pd(s3, s2);
      auto sq2 = [&](std::size_t j) {
        const __m128d dv = _mm_sub_pd(_mm_loadh_pd(_mm_load_sd(&body[j].v), &body[j + 1].v), mu);
        return _mm_mul_pd(dv, dv);
      };
      for (; i + 4 <= hi; i += 4) s01 = _mm_add_pd(s01, sq2(i)), s23 = _mm_add_pd(s23, sq2(i + 2));
      _mm_storel_pd(&s0, s01), _mm_storeh_pd(&s1, s01), _mm_storel_pd(&s2, s23), _mm_storeh_pd(&s3, s23);
#endif
      for (; i + 4 <= hi; i += 4) s0 += sq(i), s1 += sq(i + 1), s2 += sq(i + 2), s3 += sq(i + 3);
      for (; i < hi; ++i) s0 += sq(i);
    });
    p.spread = m * ((s0 + s1) + (s2 + s3));
  }
  // Moments and cluster scan of an equal-mass domain: one pass for the sums of
  // v and the clusters (sample_sweep.hpp) in runs, the general scan for the
  // runs that need it, then the spread's pass.
  void sweep_equal(const Domain& d, double t, bool ring, StretchPart& p, ClusterScan& scan,
                   PeriodWrap& wrap) const {
#if defined(__SSE2__)
    double s[4] = {0, 0, 0, 0};
    const typename Engine::Body* body = e_.body_.data();
    for_ranges(d, [&](std::size_t lo, std::size_t hi) {
      for (std::size_t b = lo; b < hi; b += run) {
        const std::size_t n = std::min(run, hi - b);
        const bool closes = b == 0 && lo != d.head;
        const bool swept = ring ? sweep_run<true>(body + b, n, t, e_.m0_, b, closes, s, scan, wrap)
                                : sweep_run<false>(body + b, n, t, e_.m0_, b, closes, s, scan, wrap);
        if (!swept) scan_run(b, n, t, ring, closes, scan, wrap);
      }
      p.bodies += hi - lo;
    });
    spread_equal(d, s, p);
#else
    moments_equal(d, p);
    for_ranges(d, [&](std::size_t lo, std::size_t hi) {
      for (std::size_t b = lo; b < hi; b += run)
        scan_run(b, std::min(run, hi - b), t, ring, b == 0 && lo != d.head, scan, wrap);
    });
#endif
  }
  // The cluster scan of bodies b .. b + n - 1 (equal masses, n <= run): positions
  // at t wrapped together, then the pairs. closes: body b closes the chain.
  void scan_run(std::size_t b, std::size_t n, double t, bool ring, bool closes, ClusterScan& scan,
                PeriodWrap& wrap) const {
    RunBuffer r;
    for (std::size_t k = 0; k < n; ++k)
      r.x[k] = e_.body_[b + k].at(t), r.v[k] = e_.body_[b + k].v, r.m[k] = e_.m0_;
    r.scan(n, b, b + n - 1, closes, ring, scan, wrap);
  }
  // The moments of a linked domain, and its cluster scan in runs of up to
  // `run` bodies gathered in the spread's pass (the bodies read there once), a
  // new run at the body that closes the chain (its index below its left one's).
  void scan_linked(const Domain& d, double t, bool ring, StretchPart& p, ClusterScan& scan,
                   PeriodWrap& wrap) const {
    RunBuffer r;
    std::size_t n = 0, first = d.head, previous = d.head;
    bool closes = false;
    moments_linked(d, p, [&](std::size_t i) {
      const bool closing = i < previous;
      if (n == run || closing) r.scan(n, first, previous, closes, ring, scan, wrap), n = 0;
      if (n == 0) first = i, closes = closing;
      r.x[n] = e_.body_[i].at(t), r.v[n] = e_.body_[i].v, r.m[n] = e_.mass_[i], ++n;
      previous = i;
    });
    r.scan(n, first, previous, closes, ring, scan, wrap);
  }
  static constexpr std::size_t run = 256;  // bodies per run of the scan (a multiple of 4)
  // A run's positions at t, velocities and masses, handed to the scan
  // (ClusterScan::add_run) with its positions wrapped together on a ring.
  struct RunBuffer {
    std::array<double, run> x, w, v, m;
    void scan(std::size_t n, std::size_t first, std::size_t last, bool closes, bool ring, ClusterScan& s,
              PeriodWrap& wrap) {
      if (n == 0) return;
      if (ring) wrap.wrap_all(x.data(), w.data(), n);
      s.add_run(ring ? w.data() : x.data(), v.data(), m.data(), n, first, last, closes);
    }
  };
  // f(lo, hi) for the index ranges of d's bodies (equal masses): one, or two
  // where the domain wraps past the last body of a ring.
  template <class F>
  void for_ranges(const Domain& d, F&& f) const {
    if (d.head <= d.tail) return f(d.head, d.tail + 1);
    f(d.head, e_.n_);
    f(0, d.tail + 1);
  }
  ClusterPart sorted_of(const Domain& d, double t, const SampleSpec& spec,
                        const ClusterPart& streamed) const {
    std::vector<ScanBody> bodies;
    for_each(d, [&](std::size_t i) {
      const double x = e_.body_[i].at(t);
      bodies.push_back({spec.ring ? wrap_into(x, spec.L) : x, e_.body_[i].v, e_.mass(i)});
    });
    return sorted_part(std::move(bodies), streamed.first_index, streamed.last_index, spec);
  }

  const Engine& e_;
};

// The samples of a run of sub-windows: the times, each domain's part of the
// samples of the current sub-window, and their combination in domain order.
// State of one sub-window only (nothing is kept across sub-windows but `next`).
class SampleBatch {
 public:
  // on_sample(t, moments, clusters): clusters is 0 unless spec_at(t).clusters.
  using OnSample = std::function<void(double, const SampleMoments&, std::size_t)>;
  // spec_at(t): what the sample at time t measures (asked once per time).
  template <class SpecAt>
  SampleBatch(const std::vector<double>& times, SpecAt&& spec_at, OnSample on_sample)
      : times_(times), on_sample_(std::move(on_sample)) {
    for (double t : times) specs_.push_back(spec_at(t));
  }

  // Samples not yet taken.
  bool pending() const { return next_ < times_.size(); }
  // The samples of a sub-window that runs to `end` (inclusive or not): those
  // before it, from the next one; `members` of the team will take parts.
  void open(double end, bool inclusive, std::size_t domains, std::size_t members) {
    first_ = next_, count_ = 0;
    while (first_ + count_ < times_.size() &&
           (times_[first_ + count_] < end || (inclusive && times_[first_ + count_] <= end)))
      ++count_;
    domains_ = domains;
    // A larger batch: the smaller one's parts are freed first, so that both
    // are never held at once (assign would make the new before freeing the old).
    if (domains * count_ > parts_.capacity()) parts_ = std::vector<StretchPart>();
    parts_.assign(domains * count_, StretchPart{});
    sorted_.assign(members, {});
  }
  std::size_t count() const { return count_; }
  double time(std::size_t k) const { return times_[first_ + k]; }
  const SampleSpec& spec(std::size_t k) const { return specs_[first_ + k]; }
  // Domain d's part of sample k, taken by `member`.
  template <class Sampler>
  void take(const Sampler& sampler, Domain& dom, std::size_t d, std::size_t k, std::size_t member) {
    std::optional<ClusterPart> sorted;
    parts_[d * count_ + k] = sampler.take(dom, time(k), spec(k), sorted);
    if (sorted) sorted_[member].push_back({d, k, *sorted});
  }
  // Sample k's part of domain d.
  StretchPart& part(std::size_t d, std::size_t k) { return parts_[d * count_ + k]; }
  // Sample k, when every domain reached it, to on_sample.
  void deliver(std::size_t k) {
    for (std::size_t d = 0; d < domains_; ++d)
      if (!part(d, k).taken) return;
    const SampleMoments moments = combine_moments(&part(0, k), domains_, count_);
    on_sample_(time(k), moments, spec(k).clusters ? clusters(k, moments.bodies) : 0);
  }
  void close() { next_ = first_ + count_; }

 private:
  struct Sorted {
    std::size_t domain, sample;
    ClusterPart part;
  };
  // The count from the parts as streamed; where they were out of order, with the
  // sorted parts in place of the streamed ones.
  std::size_t clusters(std::size_t k, std::size_t bodies) {
    std::vector<const ClusterPart*> parts(domains_);
    for (std::size_t d = 0; d < domains_; ++d) parts[d] = &part(d, k).clusters;
    const ClusterCount streamed = count_clusters(parts, bodies, spec(k));
    if (streamed.ordered) return streamed.count;
    for (const std::vector<Sorted>& member : sorted_)
      for (const Sorted& s : member)
        if (s.sample == k) parts[s.domain] = &s.part;
    return count_clusters(parts, bodies, spec(k)).count;
  }

  const std::vector<double>& times_;
  std::vector<SampleSpec> specs_;  // of each time
  OnSample on_sample_;
  std::size_t next_ = 0, first_ = 0, count_ = 0, domains_ = 0;
  std::vector<StretchPart> parts_;           // [domain * count + sample]
  std::vector<std::vector<Sorted>> sorted_;  // per member of the team
};

}  // namespace shockgas::particles::detail
