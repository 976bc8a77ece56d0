#pragma once
// One domain of a window plan and its event loop (private to particles/): the
// bodies head .. tail between two cuts, a tournament tree over their pair slots
// head .. tail - 1, and the collisions inside, in time order. Used by
// WindowScheduler, which runs many domains at once.
//
// The step of the equal-mass layout is the engine's hot loop. It computes the
// same numbers as EventEngine::collide_equal and contact_time, operation for
// operation (so the collisions are those of the global queue, to the bit), but
// without branches on the data: which collisions are sub-threshold and which
// pairs approach is random, and a mispredicted branch costs more than the
// arithmetic it skips. The two new contact times share one packed division.
#include <array>
#include <cstdint>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "shockgas/particles/event_engine.hpp"

namespace shockgas::particles::detail {

// Aligned to a pair of cache lines: each member of the team writes its domains'
// counters at every step, and neighbours in the vector run on other members.
struct alignas(128) Domain {
  std::size_t head = 0, tail = 0;  // its first and last body (tail: left body of the next cut)
  bool empty = false;              // one body: no pair inside
  EventTree tree;                  // over slots head .. tail - 1
  double now = 0;                  // time of its last collision
  double last_x = 0;               // where
  int frozen = 0;                  // consecutive collisions at exactly the same time
  bool stalled = false;
  std::array<std::uint64_t, 3> count{};  // by CollisionKind, since the last settle
  double dissipated = 0;                 // since the last settle
  double limit = 0;                      // runs to this time (inclusive): the sub-window's end or a sample
  std::size_t sample = 0;                // samples of the sub-window it has measured

  // Whether it holds the ring's seam, the pair of bodies N - 1 and 0.
  bool wraps() const { return head > tail; }
};

// A domain whose collisions stopped advancing time (EventEngine::frozen_limit in
// a row at exactly the same time) stops: a rounding stall.
inline bool stalls(Domain& d) {
  if (d.frozen < EventEngine<false>::frozen_limit) [[likely]]
    return false;
  d.stalled = true;
  return true;
}

// max(a, 0) / g for two pairs at once, then t + that where g > 0, else +inf:
// the contact times of contact_time with tm = now = t (the bodies of both pairs
// include one that collided at t).
inline void two_contact_times(double t, double gap0, double g0, double gap1, double g1, double& out0,
                              double& out1) {
#if defined(__SSE2__)
  const __m128d gap = _mm_set_pd(gap1, gap0), g = _mm_set_pd(g1, g0);
  const __m128d zero = _mm_setzero_pd();
  // std::max(gap, 0.0) keeps gap unless gap < 0: maxpd(0, gap) returns gap
  // unless 0 > gap (its second operand on equality and NaN, as std::max).
  const __m128d when = _mm_add_pd(_mm_set1_pd(t), _mm_div_pd(_mm_max_pd(zero, gap), g));
  const __m128d approach = _mm_cmpgt_pd(g, zero);
  const __m128d out =
      _mm_or_pd(_mm_and_pd(approach, when), _mm_andnot_pd(approach, _mm_set1_pd(EventTree::never)));
  out0 = _mm_cvtsd_f64(out);
  out1 = _mm_cvtsd_f64(_mm_unpackhi_pd(out, out));
#else
  out0 = g0 > 0 ? t + std::max(gap0, 0.0) / g0 : EventTree::never;
  out1 = g1 > 0 ? t + std::max(gap1, 0.0) / g1 : EventTree::never;
#endif
}

template <bool Linked>
class DomainStepper;

// Equal masses, bounces only.
template <>
class DomainStepper<false> {
 public:
  using Engine = EventEngine<false>;
  explicit DomainStepper(Engine& e) : e_(e), bounce_(e.rule(), e.m0_) {}

  // The domain's next collision if its time is <= limit; false when there is
  // none, or when the domain stalls (then stalled is set).
  [[gnu::always_inline]] bool step(Domain& d, double limit) {
    return d.wraps() ? step<true>(d, limit) : step<false>(d, limit);
  }

 private:
  // The step of a domain that holds the ring's seam (Wraps) or not. Without it
  // the neighbours of i are i - 1 and i + 1 and no position is shifted by L. A
  // position is shifted only where the pair wraps, not by +0.0 elsewhere: the
  // same numbers (x - 0.0 is x; (x + 0.0) - y differs from x - y only in the
  // sign of a zero gap, whose contact time t + (+-0) / g is t).
  template <bool Wraps>
  [[gnu::always_inline]] bool step(Domain& d, double limit) {
    const double t = d.tree.top_time();
    if (t > limit) return false;
    const std::size_t n = e_.n_;
    auto after = [n](std::size_t s) { return !Wraps || s + 1 != n ? s + 1 : 0; };
    const std::size_t i = d.tree.top();
    const std::size_t j = after(i);  // inside the domain: never past a line's end
    auto* body = e_.body_.data();
    // collide_equal(i, j, t): meet, then bounce_equal with r or 1.
    const double x = body[i].at(t);
    const double v = body[i].v, u = body[j].v;
    const double g = v - u;
    const std::size_t sub = g < e_.rule_.delta;
    const double dv = by_kind(g, bounce_[0].dv(g), bounce_[1].dv(g));
    const auto [v1, u1] = exchange(v, u, dv);
    d.dissipated += bounce_[sub].lost(g);
    ++d.count[sub];
    const double xj = Wraps && j == 0 ? x - e_.L_ : x;
    body[i] = {x, v1, t};
    body[j] = {xj, u1, t};
    d.frozen = t == d.now ? d.frozen + 1 : 0;
    d.now = t;
    d.last_x = x;
    if (i == d.head || j == d.tail) [[unlikely]]
      return edge(d, i, j, t) && !stalls(d);
    // Pairs (p, i) and (j, k), both inside: contact_time with tm = now = t.
    const std::size_t p = Wraps && i == 0 ? n - 1 : i - 1;
    const std::size_t k = after(j);
    const auto& bp = body[p];
    const auto& bk = body[k];
    const double xi = Wraps && i == 0 ? x + e_.L_ : x;
    const double xk = Wraps && k == 0 ? bk.at(t) + e_.L_ : bk.at(t);
    double tp, tj;
    two_contact_times(t, xi - bp.at(t), bp.v - v1, xk - xj, u1 - bk.v, tp, tj);
    d.tree.replace_three(p, tp, tj);  // i and j separate: slot i at +inf
    return !stalls(d);
  }

  // a if g >= delta (an inelastic bounce), else b (elastic): both computed, one
  // kept by a mask, so that the new velocities do not wait for a load indexed
  // by the comparison (N = 10^6 to t = 10^4, one thread: 0.983 of the time).
  [[gnu::always_inline]] double by_kind(double g, double a, double b) const {
#if defined(__SSE2__)
    const __m128d sub = _mm_cmplt_sd(_mm_set_sd(g), _mm_set_sd(e_.rule_.delta));
    return _mm_cvtsd_f64(_mm_or_pd(_mm_and_pd(sub, _mm_set_sd(b)), _mm_andnot_pd(sub, _mm_set_sd(a))));
#else
    return g < e_.rule_.delta ? b : a;
#endif
  }

  // The slots of a collision at the domain's edge: only those inside.
  bool edge(Domain& d, std::size_t i, std::size_t j, double t) {
    std::size_t a = i, b = i;
    if (i != d.head) a = e_.left(i), d.tree.set(a, e_.contact_time(a, i, t));
    d.tree.set(i, EventTree::never);
    if (j != d.tail) b = j, d.tree.set(j, e_.contact_time(j, e_.right(j), t));
    d.tree.refresh(a, b);
    return true;
  }

  Engine& e_;
  EqualMassBounces bounce_;  // by sub-threshold: inelastic (r), elastic (1)
};

// Merges only (r = 0).
template <>
class DomainStepper<true> {
 public:
  using Engine = EventEngine<true>;
  static constexpr std::size_t none = Engine::none;
  explicit DomainStepper(Engine& e) : e_(e) {}

  bool step(Domain& d, double limit) {
    const double t = d.tree.top_time();
    if (t > limit) return false;
    const std::size_t i = d.tree.top();
    const std::size_t j = e_.right(i);  // inside the domain: never none
    d.frozen = t == d.now ? d.frozen + 1 : 0;
    d.now = t;
    ++d.count[static_cast<int>(CollisionKind::merge)];
    e_.merge(i, j, t, d.dissipated, d.last_x);
    const std::size_t p = i != d.head ? e_.left(i) : none;
    if (j == d.tail) {
      d.tail = i;  // i now faces the next cut: its slot is the cut's
      d.tree.set(i, EventTree::never);
      e_.slot_[j] = EventTree::never;  // the old cut's slot, in no tree
    } else {
      d.tree.set(j, EventTree::never);
      d.tree.set(i, e_.contact_time(i, e_.right(i), t));
      d.tree.refresh_path(j);
    }
    if (p != none) d.tree.set(p, e_.contact_time(p, i, t)), d.tree.refresh_path(p);
    d.tree.refresh_path(i);
    return !stalls(d);
  }

 private:
  Engine& e_;
};

}  // namespace shockgas::particles::detail
