#pragma once
// The event-driven engine (private to particles/): point bodies on a ring or an
// open line, only neighbours collide, so the bodies never change order.
//
// Body i keeps its position x at its own local time t and its velocity v
// (x(s) = x + v (s - t), lazy positions). Pair slot i is body i with its right
// neighbour; its predicted contact time sits in SlotTimes. A collision changes
// the velocities of two bodies, hence only the times of the slots left(i), i and
// right(i). Who orders the events: the engine's own global queue (run_until), or
// a WindowScheduler, which runs stretches of the chain with trees of their own
// over the same slot times.
//
// Two layouts, chosen once per run:
//  * Linked = false: equal masses, no merges; neighbours are i +- 1 (mod N on the
//    ring). 24 bytes per body + 8 per slot time + 1.5 per slot for a tree =
//    33.5 bytes per particle.
//  * Linked = true: masses and merges; the live bodies form a doubly linked list
//    (a ring on the ring). A merge keeps the left body, unlinks the right one and
//    sets its slot to +inf. 33.5 + 8 (mass) + 8 (links) = 49.5 bytes per particle.
//
// Ring geometry: positions are unrolled (never wrapped while running); the pair
// whose right body has the lower index wraps, the right body counted at x + L.
// So in chain order from any body the unrolled positions never decrease.
#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "shockgas/particles/collision.hpp"
#include "shockgas/particles/event_tree.hpp"
#include "shockgas/particles/huge_page_allocator.hpp"
#include "shockgas/particles/params.hpp"

namespace shockgas::particles::detail {

template <bool Linked>
class WindowScheduler;
template <bool Linked>
class WindowPlanner;
template <bool Linked>
class DomainStepper;
template <bool Linked>
class DomainSampler;
struct StateIo;

// Why run_until returned. stall: delta > 0 (or r = 0, 1), where no collapse is
// possible, but time stopped advancing anyway (see run_until).
enum class EngineStop { reached, collapse, stall, halted };

template <bool Linked>
class EventEngine {
 public:
  static constexpr std::uint32_t none = 0xFFFFFFFFu;
  // Collisions between two looks at the watch and at inelastic collapse.
  static constexpr std::uint64_t check_every = kGlobalQueueCheckEvery;
  // Consecutive collisions without time advancing that mean inelastic collapse.
  static constexpr int stall_limit = 256;
  // Consecutive collisions at exactly the same time that mean a rounding stall
  // when no collapse is possible: legitimate bursts (a multi-body contact of k
  // bodies at one point resolves in ~k^2 / 2 collisions) stay far below, and
  // 2^24 collisions take about a second.
  static constexpr int frozen_limit = 1 << 24;

  // n bodies; fill(first, count, x, v, m) is called for consecutive chunks and
  // writes bodies first .. first + count - 1 (sorted by x, ring: inside [0, L);
  // all masses equal unless Linked). The global queue is built only when asked
  // for (use_global_queue).
  template <class Fill>
  EventEngine(std::size_t n, double L, bool ring, const CollisionRule& rule, Fill&& fill)
      : EventEngine(n, L, ring, rule) {
    slot_.reset(n_);
    load_bodies(fill);
    if constexpr (Linked) {
      link_all();
      for (std::size_t i = 0; i < n_; ++i) slot_[i] = pair_time(i, 0.0);
    }
  }
  // Without bodies yet: they come from a saved state (StateIo::restore).
  EventEngine(std::size_t n, double L, bool ring, const CollisionRule& rule)
      : L_(L), ring_(ring), rule_(rule), n_(n), alive_(n) {
    const bool collapse_possible = rule_.collapse_possible();
    step_scale_ = collapse_possible ? 1e-12 : 0.0;
    window_scale_ = collapse_possible ? 1e-10 : -1.0;
    step_limit_ = collapse_possible ? stall_limit : frozen_limit;
  }

  // Builds the global event queue over the slot times as they are (needed by run_until).
  void use_global_queue() { tree_.attach(slot_, 0, n_ - 1); }

  // Processes every collision at time <= t_stop on the global queue; then now() =
  // t_stop unless stopped early. watch(now, collisions) is called every
  // check_every collisions and returns false to halt.
  //
  // Inelastic collapse (delta = 0, 0 < r < 1): a few bodies collide ever faster,
  // the gaps fall below rounding and the contact times stop advancing; left alone,
  // rounding would eventually let the bodies escape with meaningless velocities.
  // Detected as `stall_limit` consecutive collisions that advance time by less
  // than 1e-12 max(1, t), or a window of check_every collisions advancing it by
  // less than 1e-10 max(1, t).
  //
  // With a threshold (delta > 0) there is no collapse: every collision either
  // dissipates at least (1 - r^2) mu delta^2 / 2 or is sub-threshold (a merge, or
  // an elastic bounce that sorts the velocities of bodies in contact), so only
  // finitely many collisions happen at any instant. Dense clusters do squeeze
  // their gaps to rounding level, and then hundreds of collisions legitimately
  // fall within 1e-12 t (a gap of one ulp of x closed at speed ~delta); those are
  // resolved, not stopped. Only `frozen_limit` consecutive collisions at exactly
  // the same time stop the run, as EngineStop::stall, so that no rounding
  // accident can hang it.
  template <class Watch>
  EngineStop run_until(double t_stop, Watch&& watch) {
    if (rule_.law) return run_queue<true>(t_stop, watch);
    return run_queue<false>(t_stop, watch);
  }

  std::size_t size() const { return n_; }
  double length() const { return L_; }
  bool ring() const { return ring_; }
  const CollisionRule& rule() const { return rule_; }
  double now() const { return now_; }
  std::size_t alive() const { return alive_; }
  // Collisions by kind (CollisionKind order), and all of them.
  std::uint64_t count(CollisionKind kind) const { return count_[static_cast<int>(kind)]; }
  std::uint64_t collisions() const { return count_[3]; }
  double dissipated() const { return dissipated_; }
  // Position (unrolled) of the body of the last collision.
  double last_position() const { return last_x_; }
  // The predicted contact time of pair slot i (body i and its right neighbour) as
  // the queue holds it; +inf for none.
  double slot_time(std::size_t i) const { return slot_[i]; }

  // Visits the live bodies in chain order from body 0: f(index, x at time t
  // (unrolled), v, m); those at chain positions begin .. end - 1 only (the k-th
  // live body is at position k; without merges body k).
  template <class F>
  void for_each_body(double t, F&& f, std::size_t begin = 0,
                     std::size_t end = std::numeric_limits<std::size_t>::max()) const {
    if constexpr (Linked) {
      std::size_t k = 0;
      for (std::size_t i = 0; i < n_ && k < end; ++i)
        if (mass_[i] != 0.0 && k++ >= begin) f(i, body_[i].at(t), body_[i].v, mass(i));
    } else {
      for (std::size_t i = begin; i < std::min(end, n_); ++i) f(i, body_[i].at(t), body_[i].v, mass(i));
    }
  }

 private:
  friend class WindowScheduler<Linked>;
  friend class WindowPlanner<Linked>;
  friend class DomainStepper<Linked>;
  friend class DomainSampler<Linked>;
  friend struct StateIo;
  struct Body {
    double x;                                              // position at local time t [length], unrolled
    double v;                                              // velocity [length/time]
    double t;                                              // local time [time]
    double at(double s) const { return x + v * (s - t); }  // position at time s
  };

  // The bodies in chunks, each array written once (appended, not zeroed first);
  // with equal masses also the slot times of each chunk's pairs while its bodies
  // are in cache (Linked: after link_all).
  template <class Fill>
  void load_bodies(Fill& fill) {
    constexpr std::size_t chunk = 4096;
    std::vector<double> x(std::min(chunk, n_)), v(x.size()), m(x.size());
    body_.reserve(n_);
    if constexpr (Linked) mass_.reserve(n_);
    for (std::size_t lo = 0; lo < n_; lo += chunk) {
      const std::size_t size = std::min(chunk, n_ - lo);
      fill(lo, size, x.data(), v.data(), m.data());
      if (lo == 0) m0_ = m[0];
      for (std::size_t k = 0; k < size; ++k) {
        body_.push_back({x[k], v[k], 0.0});
        if constexpr (Linked) mass_.push_back(m[k]);
        assert(Linked || m[k] == m0_);
      }
      if constexpr (!Linked) loaded_slot_times(lo > 0 ? lo - 1 : 0, lo + size - 1);  // right body loaded
    }
    if constexpr (!Linked) slot_[n_ - 1] = pair_time(n_ - 1, 0.0);
  }
  // slot_[i] = pair_time(i, 0) for i = first .. last - 1 (pairs (i, i + 1), equal
  // masses): contact_time's operations, two pairs at a time without branches.
  void loaded_slot_times(std::size_t first, std::size_t last) {
    std::size_t i = first;
#if defined(__SSE2__)
    const double* q = &body_[0].x;  // x, v, t of body i at q + 3 i
    const __m128d zero = _mm_setzero_pd(), never = _mm_set1_pd(EventTree::never);
    auto two = [&](std::size_t j, std::size_t field) {
      return _mm_set_pd(q[3 * j + 3 + field], q[3 * j + field]);
    };
    for (; i + 2 <= last; i += 2) {
      const __m128d ax = two(i, 0), av = two(i, 1), at = two(i, 2);  // bodies i, i + 1
      const __m128d cx = two(i + 1, 0), cv = two(i + 1, 1), ct = two(i + 1, 2);
      const __m128d g = _mm_sub_pd(av, cv);
      const __m128d tm = _mm_max_pd(ct, at);  // std::max(a.t, c.t): c.t unless a.t >= c.t (or NaN)
      const __m128d c_at = _mm_add_pd(cx, _mm_mul_pd(cv, _mm_sub_pd(tm, ct)));
      const __m128d a_at = _mm_add_pd(ax, _mm_mul_pd(av, _mm_sub_pd(tm, at)));
      const __m128d gap = _mm_sub_pd(_mm_add_pd(c_at, zero), a_at);  // shift 0
      // std::max(y, 0.0) is maxpd(0, y): y unless 0 > y (also for NaN and -0).
      const __m128d when = _mm_max_pd(zero, _mm_add_pd(tm, _mm_div_pd(_mm_max_pd(zero, gap), g)));
      const __m128d approach = _mm_cmpgt_pd(g, zero);
      const __m128d out = _mm_or_pd(_mm_and_pd(approach, when), _mm_andnot_pd(approach, never));
      _mm_storel_pd(&slot_[i], out), _mm_storeh_pd(&slot_[i + 1], out);
    }
#endif
    for (; i < last; ++i) slot_[i] = pair_time(i, 0.0);
  }
  void link_all() {
    next_.resize(n_);
    prev_.resize(n_);
    for (std::size_t i = 0; i < n_; ++i) {
      next_[i] = static_cast<std::uint32_t>(i + 1);
      prev_[i] = static_cast<std::uint32_t>(i) - 1;  // none for i = 0
    }
    next_[n_ - 1] = ring_ ? 0 : none;
    prev_[0] = ring_ ? static_cast<std::uint32_t>(n_ - 1) : none;
  }

  double mass(std::size_t i) const {
    if constexpr (Linked) return mass_[i];
    return m0_;
  }
  bool live(std::size_t i) const {
    if constexpr (Linked) return mass_[i] != 0.0;
    return true;
  }
  // Starts the loads of an event's bodies and tree path at once (they miss at large N).
  void prefetch(std::size_t i) const {
    const Body* b = body_.data() + i;
    prefetch_line(b - (i > 0));
    prefetch_line(b + 2 - (i + 2 >= n_) * 2);
    tree_.prefetch_path(i);
  }
  // Right neighbour of body i, or none.
  std::size_t right(std::size_t i) const {
    if constexpr (Linked) {
      const std::uint32_t j = next_[i];
      return j == i ? none : j;
    }
    if (i + 1 < n_) return i + 1;
    return ring_ ? 0 : none;
  }
  std::size_t left(std::size_t i) const {
    if constexpr (Linked) {
      const std::uint32_t j = prev_[i];
      return j == i ? none : j;
    }
    if (i > 0) return i - 1;
    return ring_ ? n_ - 1 : none;
  }

  // Contact time of slot i: the gap closes at speed g = v_i - v_j. now: the time
  // of the collision being processed.
  double pair_time(std::size_t i, double now) const {
    if (!live(i)) return EventTree::never;
    const std::size_t j = right(i);
    if (j == none) return EventTree::never;
    return contact_time(i, j, now);
  }
  // Contact time of the pair (i, j = right(i)), which exists.
  double contact_time(std::size_t i, std::size_t j, double now) const {
    return contact_time(body_[i], body_[j], shift(i, j), now);
  }
  // Where the ring's wrapping pair counts its right body: at x + L.
  double shift(std::size_t i, std::size_t j) const { return j <= i ? L_ : 0.0; }
  // Contact time of body a and its right neighbour c, counted at x + shift.
  static double contact_time(const Body& a, const Body& c, double shift, double now) {
    const double g = a.v - c.v;
    const double tm = std::max(a.t, c.t);
    const double gap = (c.at(tm) + shift) - a.at(tm);
    // Never before now: a gap closed by rounding is a contact now, so time never
    // runs backwards.
    const double t = std::max(tm + std::max(gap, 0.0) / g, now);
    return g > 0 ? t : EventTree::never;
  }

  // run_until's loop, for a rule with a restitution law or without
  // (CollisionRule::restitution).
  template <bool HasLaw, class Watch>
  EngineStop run_queue(double t_stop, Watch& watch) {
    while (tree_.top_time() <= t_stop) {
      const std::size_t i = tree_.top();
      prefetch(i);
      // Likely the event after this one (2/3 of the time): its memory loads
      // overlap this event's work. Pays off only when the arrays miss the caches.
      if (tree_.hinting()) prefetch(std::min(tree_.hint(), n_ - 1));
      const double t = tree_.top_time();
      stall_ = t - now_ <= step_scale_ * std::max(1.0, std::abs(now_)) ? stall_ + 1 : 0;
      if (stall_ >= step_limit_) return step_scale_ > 0 ? EngineStop::collapse : EngineStop::stall;
      collide<HasLaw>(i);
      if ((++count_[3] & (check_every - 1)) == 0) {
        if (now_ - window_start_ <= window_scale_ * std::max(1.0, std::abs(now_)))
          return EngineStop::collapse;
        window_start_ = now_;
        if (!watch(now_, count_[3])) return EngineStop::halted;
      }
    }
    now_ = std::max(now_, t_stop);
    return EngineStop::reached;
  }

  // The collision at the top of the global queue.
  template <bool HasLaw>
  void collide(std::size_t i) {
    const std::size_t j = right(i);
    assert(j != none);
    const double t = tree_.top_time();
    now_ = t;
    if constexpr (Linked) {
      const double g = body_[i].v - body_[j].v;
      const CollisionKind kind = rule_.classify(g);
      ++count_[static_cast<int>(kind)];
      if (kind == CollisionKind::merge) {
        merge(i, j, t, dissipated_, last_x_);
        --alive_;
        return after_merge(i, j);
      }
      last_x_ = meet(i, j, t);
      const double r = rule_.template restitution<HasLaw>(kind, g);
      dissipated_ += bounce(body_[i].v, body_[j].v, mass_[i], mass_[j], r);
    } else {
      ++count_[collide_equal<HasLaw>(i, j, t, dissipated_, last_x_)];
    }
    refresh(left(i), i, j, true);
  }
  // Moves bodies i and j = right(i) to their contact point at time t; returns it.
  double meet(std::size_t i, std::size_t j, double t) {
    Body& a = body_[i];
    Body& c = body_[j];
    const double x = a.at(t);
    a.x = x;
    a.t = t;
    c.x = x - shift(i, j);
    c.t = t;
    return x;
  }
  // The collision of equal-mass bodies i and j = right(i) at time t: adds the
  // energy lost to dissipated, stores the contact point in x; returns the
  // CollisionKind index (inelastic 0, elastic 1).
  template <bool HasLaw>
  int collide_equal(std::size_t i, std::size_t j, double t, double& dissipated, double& x) {
    x = meet(i, j, t);
    double& v = body_[i].v;
    double& u = body_[j].v;
    const double g = v - u;
    const bool sub = g < rule_.delta;
    const CollisionKind kind = sub ? CollisionKind::elastic : CollisionKind::inelastic;
    dissipated += bounce_equal(v, u, m0_, rule_.template restitution<HasLaw>(kind, g));
    return sub;
  }
  // Body j = right(i) joins body i at time t (Linked): velocities, masses and
  // links; the slots are the caller's. Adds the energy lost to dissipated and
  // stores the contact point in x.
  void merge(std::size_t i, std::size_t j, double t, double& dissipated, double& x) {
    x = meet(i, j, t);
    const Merged out = particles::merge(body_[i].v, body_[j].v, mass_[i], mass_[j]);
    body_[i].v = out.v;
    mass_[i] = out.m;
    mass_[j] = 0.0;
    dissipated += out.dissipated;
    const std::uint32_t k = next_[j];  // i itself when i and j were alone on a ring
    next_[i] = k;
    if (k != none) prev_[k] = static_cast<std::uint32_t>(i);
  }
  // The global queue after body j joined body i.
  void after_merge(std::size_t i, std::size_t j) {
    tree_.set(j, EventTree::never);
    tree_.refresh_path(j);
    refresh(left(i), i, none, false);
  }

  // Recomputes slots p (left of i, may be none), i and j (right of i, may be none)
  // on the global queue. bounced: i and j just bounced, so they separate
  // (g -> -r g <= 0): no event.
  void refresh(std::size_t p, std::size_t i, std::size_t j, bool bounced) {
    if (p != none) tree_.set(p, pair_time(p, now_));
    tree_.set(i, bounced ? EventTree::never : pair_time(i, now_));
    if (j != none) tree_.set(j, pair_time(j, now_));
    if (p != none && j != none && p + 1 == i && i + 1 == j) return tree_.refresh(p, j);
    if (p != none && p + 1 == i && j == none) return tree_.refresh(p, i);
    if (p != none) tree_.refresh_path(p);
    tree_.refresh_path(i);
    if (j != none) tree_.refresh_path(j);
  }

  double L_;
  bool ring_;
  CollisionRule rule_;
  std::size_t n_;
  std::size_t alive_;
  double m0_ = 1.0;
  std::vector<Body, HugePageAllocator<Body>> body_;
  SlotTimes slot_;                                       // contact time of every pair slot
  std::vector<double, HugePageAllocator<double>> mass_;  // Linked only; 0 = merged away
  std::vector<std::uint32_t, HugePageAllocator<std::uint32_t>> next_, prev_;  // Linked only
  EventTree tree_;                                                            // the global queue, when used
  double now_ = 0.0;
  double window_start_ = 0.0;
  int stall_ = 0;            // consecutive collisions advancing time by <= step_scale_ max(1, t)
  double step_scale_ = 0;    // 1e-12 if collapse is possible, else 0 (exactly frozen)
  double window_scale_ = 0;  // 1e-10 if collapse is possible, else -1 (never)
  int step_limit_ = 0;       // stall_limit or frozen_limit
  double last_x_ = 0.0;
  double dissipated_ = 0.0;
  std::array<std::uint64_t, 4> count_{};  // inelastic, elastic, merge, all
};

}  // namespace shockgas::particles::detail
