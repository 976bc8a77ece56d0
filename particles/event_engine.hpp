#pragma once
// The event-driven engine (private to particles/): point bodies on a ring or an
// open line, only neighbours collide, so the bodies never change order.
//
// Body i keeps its position x at its own local time t and its velocity v
// (x(s) = x + v (s - t), lazy positions). Pair slot i is body i with its right
// neighbour; its predicted contact time sits in a tournament tree. A collision
// changes the velocities of two bodies, hence only the times of the slots
// left(i), i and right(i).
//
// Two layouts, chosen once per run:
//  * Linked = false: equal masses, no merges; neighbours are i +- 1 (mod N on the
//    ring). 24 bytes per body + 8 per slot time + 4 per slot for the tree over
//    blocks of 8 slots = 35 bytes per particle (32 when a WindowScheduler drives
//    it: no global tree, a slot time each).
//  * Linked = true: masses and merges; the live bodies form a doubly linked list
//    (a ring on the ring). A merge keeps the left body, unlinks the right one and
//    sets its slot to +inf. 35 + 8 (mass) + 8 (links) = 51 bytes per particle.
//
// Ring geometry: positions are unrolled (never wrapped while running); the pair
// whose right body has the lower index wraps, the right body counted at x + L.
#include <array>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <vector>

#include "event_tree.hpp"
#include "huge_page_allocator.hpp"
#include "shockgas/core/bodies.hpp"
#include "shockgas/particles/collision.hpp"

namespace shockgas::particles::detail {

class WindowScheduler;

// Why run_until returned. stall: delta > 0 (or r = 0, 1), where no collapse is
// possible, but time stopped advancing anyway (see run_until).
enum class EngineStop { reached, collapse, stall, halted };

template <bool Linked>
class EventEngine {
 public:
  static constexpr std::uint32_t none = 0xFFFFFFFFu;
  // Collisions between two looks at the watch and at inelastic collapse.
  static constexpr std::uint64_t check_every = 1u << 14;
  // Consecutive collisions without time advancing that mean inelastic collapse.
  static constexpr int stall_limit = 256;
  // Consecutive collisions at exactly the same time that mean a rounding stall
  // when no collapse is possible: legitimate bursts (a multi-body contact of k
  // bodies at one point resolves in ~k^2 / 2 collisions) stay far below, and
  // 2^24 collisions take about a second.
  static constexpr int frozen_limit = 1 << 24;

  // initial: sorted by x (ring: inside [0, L)); all masses equal unless Linked.
  // global_queue = false leaves the global event queue empty, for a run that a
  // WindowScheduler drives (Linked = false only); run_until needs it.
  EventEngine(const Bodies& initial, double L, bool ring, const CollisionRule& rule, bool global_queue = true)
      : L_(L), ring_(ring), rule_(rule), n_(initial.size()), alive_(initial.size()) {
    body_.resize(n_);
    for (std::size_t i = 0; i < n_; ++i) body_[i] = {initial.x[i], initial.v[i], 0.0};
    m0_ = initial.m[0];
    if constexpr (Linked) {
      mass_ = initial.m;
      next_.resize(n_);
      prev_.resize(n_);
      for (std::size_t i = 0; i < n_; ++i) {
        next_[i] = static_cast<std::uint32_t>(i + 1);
        prev_[i] = static_cast<std::uint32_t>(i) - 1;  // none for i = 0
      }
      next_[n_ - 1] = ring_ ? 0 : none;
      prev_[0] = ring_ ? static_cast<std::uint32_t>(n_ - 1) : none;
    }
    if (global_queue) build_queue();
    const bool collapse_possible = rule_.collapse_possible();
    step_scale_ = collapse_possible ? 1e-12 : 0.0;
    window_scale_ = collapse_possible ? 1e-10 : -1.0;
    step_limit_ = collapse_possible ? stall_limit : frozen_limit;
  }

  // Processes every collision at time <= t_stop; then now() = t_stop unless
  // stopped early. watch(now, collisions) is called every check_every collisions
  // and returns false to halt.
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
    assert(tree_.size() == n_);
    while (tree_.top_time() <= t_stop) {
      const std::size_t i = tree_.top();
      prefetch(i);
      // Likely the event after this one (2/3 of the time): its memory loads
      // overlap this event's work. Pays off only when the arrays miss the caches.
      if (tree_.hinting()) prefetch(std::min(tree_.hint(), n_ - 1));
      const double t = tree_.top_time();
      stall_ = t - now_ <= step_scale_ * std::max(1.0, std::abs(now_)) ? stall_ + 1 : 0;
      if (stall_ >= step_limit_) return step_scale_ > 0 ? EngineStop::collapse : EngineStop::stall;
      collide(i);
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

  // (Re)builds the global event queue from the bodies as they are at now().
  void build_queue() {
    tree_.assign(n_, [&](std::size_t i) { return pair_time(i, now_); });
  }

  double now() const { return now_; }
  std::size_t alive() const { return alive_; }
  // Collisions by kind (CollisionKind order), and all of them.
  std::uint64_t count(CollisionKind kind) const { return count_[static_cast<int>(kind)]; }
  std::uint64_t collisions() const { return count_[3]; }
  double dissipated() const { return dissipated_; }
  // Position (unrolled) of the body of the last collision.
  double last_position() const { return last_x_; }

  // Visits the live bodies in order: f(index, x at time t (unrolled), v, m).
  template <class F>
  void for_each_body(double t, F&& f) const {
    for (std::size_t i = 0; i < n_; ++i) {
      if constexpr (Linked)
        if (mass_[i] == 0.0) continue;
      const Body& b = body_[i];
      f(i, b.at(t), b.v, mass(i));
    }
  }

 private:
  friend class WindowScheduler;
  struct Body {
    double x;                                              // position at local time t [length], unrolled
    double v;                                              // velocity [length/time]
    double t;                                              // local time [time]
    double at(double s) const { return x + v * (s - t); }  // position at time s
  };

  double mass(std::size_t i) const {
    if constexpr (Linked) return mass_[i];
    return m0_;
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

  void collide(std::size_t i) {
    const std::size_t j = right(i);
    assert(j != none);
    const double t = tree_.top_time();
    now_ = t;
    if constexpr (Linked) {
      const double g = body_[i].v - body_[j].v;
      last_x_ = meet(i, j, t);
      const CollisionKind kind = rule_.classify(g);
      ++count_[static_cast<int>(kind)];
      if (kind == CollisionKind::merge) return merge(i, j);
      dissipated_ += bounce(body_[i].v, body_[j].v, mass_[i], mass_[j], rule_.restitution(kind));
    } else {
      ++count_[collide_equal(i, j, t, dissipated_, last_x_)];
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
  int collide_equal(std::size_t i, std::size_t j, double t, double& dissipated, double& x) {
    x = meet(i, j, t);
    double& v = body_[i].v;
    double& u = body_[j].v;
    const bool sub = v - u < rule_.delta;
    dissipated += bounce_equal(v, u, m0_, sub ? 1.0 : rule_.r);
    return sub;
  }

  // Body j joins body i (j = right(i)).
  void merge(std::size_t i, std::size_t j) {
    const Merged out = particles::merge(body_[i].v, body_[j].v, mass_[i], mass_[j]);
    body_[i].v = out.v;
    mass_[i] = out.m;
    mass_[j] = 0.0;
    dissipated_ += out.dissipated;
    const std::uint32_t k = next_[j];
    next_[i] = k;
    if (k != none) prev_[k] = static_cast<std::uint32_t>(i);
    --alive_;
    tree_.set(j, EventTree::never);
    tree_.refresh_path(j);
    const std::size_t p = left(i);
    refresh(p, i, none, false);
  }

  // Recomputes slots p (left of i, may be none), i and j (right of i, may be none).
  // bounced: i and j just bounced, so they separate (g -> -r g <= 0): no event.
  void refresh(std::size_t p, std::size_t i, std::size_t j, bool bounced) {
    if (p != none) tree_.set(p, pair_time(p, now_));
    tree_.set(i, bounced ? EventTree::never : pair_time(i, now_));
    if (j != none) tree_.set(j, pair_time(j, now_));
    if (p != none && j != none && p + 1 == i && i + 1 == j) return tree_.refresh_range(p, j);
    if (p != none && p + 1 == i && j == none) return tree_.refresh_range(p, i);
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
  std::vector<double> mass_;                // Linked only; 0 = merged away
  std::vector<std::uint32_t> next_, prev_;  // Linked only
  EventTree tree_;
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
