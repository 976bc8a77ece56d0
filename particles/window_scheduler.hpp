#pragma once
// Runs the equal-mass engine (EventEngine<false>) in time windows over stretches
// of the chain: the same collisions as the global queue, with local memory access.
//
// Why. The global queue takes the events in time order, and the next event lies
// anywhere on the ring, so at N = 10^6 nearly every event misses the caches. And
// one event is one serial chain (contact, division, tree climb): the core idles
// between its steps.
//
// Causality. With equal masses and 0 <= r <= 1 a collision replaces the two
// velocities by convex combinations of themselves, v' = (1 - r)/2 v + (1 + r)/2 u
// and u' = (1 + r)/2 v + (1 - r)/2 u, so from time T on every velocity stays in
// [v_min, v_max] of time T, and a pair with gap G at T cannot meet before
// T + G / (v_max - v_min). Until then such a pair, a cut, separates the bodies
// on its two sides: no collision on one side can change a body on the other.
//
// A window [T, T_w):
//  * cuts: near every D-th pair (D about domain_bodies), the pair with the widest
//    gap among the D/8 pairs on either side. Cuts whose bound is below a quarter
//    of the median bound are dropped (their domains join), so that one dense
//    cluster does not shorten every window;
//  * T_w = T + min over cuts of their bound (cut_bound: G over the spread of the
//    velocities near the cut, at least G / (v_max - v_min); G less a margin for
//    rounding, see safe_gap), at most about 4 collisions per body at the last
//    window's rate, and at most t_stop;
//  * each domain (the bodies between two cuts) runs alone to T_w with its own
//    tournament tree over its pairs, small enough for the core's caches. The
//    contact times are computed by the same function from the same states as in
//    the global queue, so a domain sees the same collisions in the same order, and
//    the final state is the same to the last bit (up to the order of collisions of
//    overlapping pairs at exactly the same time: test WindowScheduler.*);
//  * two domains run at once, interleaved event by event, so that their serial
//    chains overlap in the core.
// If a window cannot advance (every cut candidate closed), or 8 windows in a row
// hold fewer than N/64 collisions, the run continues on the global queue.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "event_engine.hpp"
#include "shockgas/core/interrupt.hpp"

namespace shockgas::particles::detail {

class WindowScheduler {
 public:
  using Engine = EventEngine<false>;
  // Nominal bodies per domain: a domain's bodies and tree (~150 kB) stay in the
  // second-level cache.
  static constexpr std::size_t domain_bodies = 4096;
  // At least this many domains, and at least min_domain_bodies bodies in each.
  static constexpr std::size_t min_domains = 4;
  static constexpr std::size_t min_domain_bodies = 256;

  // True when windows are exact for n equal-mass bodies under this rule (no merges,
  // no collapse to detect) and the chain is long enough to split.
  static bool applicable(std::size_t n, const CollisionRule& rule) {
    return !rule.can_merge() && !rule.collapse_possible() && n >= min_domains * min_domain_bodies;
  }

  // e was built without its global queue (global_queue = false).
  explicit WindowScheduler(Engine& e) : e_(e) {}

  // As Engine::run_until: processes every collision at time <= t_stop.
  template <class Watch>
  EngineStop run_until(double t_stop, Watch&& watch) {
    bool halt = false;
    while (!global_) {
      const Window w = plan(t_stop);
      if (!(w.end > e_.now_) && !w.last) {  // no cut can stay open: no progress possible
        global_ = true;
        e_.build_queue();
        break;
      }
      const std::uint64_t before = e_.count_[3];
      if (run_window(w, watch, halt)) return EngineStop::stall;
      e_.now_ = std::max(e_.now_, w.end);
      // Windows that stay thin (cuts barely open: a gas in contact everywhere)
      // cost O(N) each for a few collisions; the global queue is cheaper then.
      thin_ = !w.last && e_.count_[3] - before < n() / 64 ? thin_ + 1 : 0;
      if (thin_ >= 8) global_ = true, e_.build_queue();
      if (halt) return EngineStop::halted;
      if (w.last) return EngineStop::reached;
    }
    return e_.run_until(t_stop, watch);
  }

 private:
  struct Window {
    double end = 0;                 // T_w
    bool last = false;              // end = t_stop: collisions at exactly end included
    std::vector<std::size_t> cuts;  // ascending slots
  };
  struct Stream {
    EventTree tree;  // the domain's pairs: local slot k = global slot base + k
    std::size_t base = 0;
    double now = 0;     // time of the domain's last collision
    double last_x = 0;  // its contact point
    int frozen = 0;     // consecutive collisions at exactly the same time
    bool busy = false;
    std::array<std::uint64_t, 2> count{};  // inelastic, elastic
    double dissipated = 0;
  };

  std::size_t n() const { return e_.n_; }
  std::size_t wrap(std::size_t i) const { return i >= n() ? i - n() : i; }

  // Gap of pair slot i at time t (i < n - 1 on a line).
  double gap(std::size_t i, double t) const {
    const std::size_t j = wrap(i + 1);
    return (e_.body_[j].at(t) + e_.shift(i, j)) - e_.body_[i].at(t);
  }

  // The gap of slot i at t less its rounding: a few ulps of the positions (they
  // reach L on a ring) and 1e-6 relative for the rounding of the velocities.
  double safe_gap(std::size_t i, double t) const {
    const double slack = 1e-12 * (e_.L_ + std::abs(e_.body_[i].x));
    return std::max((1.0 - 1e-6) * gap(i, t) - slack, 0.0);
  }

  // How long from t the cut c (pair c, c + 1) surely stays open. A chain of
  // collisions carries velocity from a body k to body c by moving bodies (at most
  // v_max) while c moves at least at v_min, so from body k it reaches c no sooner
  // than (x_c - x_k) / dv, dv = v_max - v_min; likewise from the right to c + 1.
  // Until t + D, then, c and c + 1 keep velocities within those of the bodies at
  // most dv D away on their side (max_L on the left, min_R on the right), and the
  // gap G closes at most at max_L - min_R: the cut holds while G > (max_L - min_R) D.
  // (The first cut to close would have to break this bound first.) Scans up to
  // `reach` bodies; never less than the global bound G / dv.
  double cut_bound(std::size_t c, double t, double dv) const {
    constexpr int reach = 64;
    const double inf = std::numeric_limits<double>::infinity();
    if (!(dv > 0)) return inf;
    const double G = safe_gap(c, t);
    const auto& body = e_.body_;
    const std::size_t r = wrap(c + 1);
    auto at = [&](std::size_t k) { return body[k].at(t); };
    const double xl = at(c), xr = at(r) + e_.shift(c, r);
    double max_l = body[c].v, min_r = body[r].v;
    // Next bodies outward and their distances (unrolled); +inf past a line's end.
    std::size_t kl = c, kr = r;
    double shift_l = 0, shift_r = e_.shift(c, r);
    auto step_left = [&]() {
      if (kl == 0 && !e_.ring_) return inf;
      if (kl == 0) shift_l -= e_.L_;
      kl = kl == 0 ? n() - 1 : kl - 1;
      return xl - (at(kl) + shift_l);
    };
    auto step_right = [&]() {
      if (kr == n() - 1 && !e_.ring_) return inf;
      if (kr == n() - 1) shift_r += e_.L_;
      kr = kr == n() - 1 ? 0 : kr + 1;
      return at(kr) + shift_r - xr;
    };
    double dl = step_left(), dr = step_right();
    const double slack = 1e-12 * (e_.L_ + std::abs(xl));  // rounding of the distances, as in safe_gap
    double bound = G / dv;
    for (int k = 0; k < 2 * reach; ++k) {
      const double horizon = (std::min(dl, dr) - slack) / dv;  // the sets are complete until then
      const double d = max_l > min_r ? G / (max_l - min_r) : inf;
      if (d <= horizon) return std::max(d, G / dv);
      bound = std::max(bound, horizon);
      if (dl <= dr) {
        max_l = std::max(max_l, body[kl].v);
        dl = std::max(dl, step_left());  // rounding aside, distances grow outward
      } else {
        min_r = std::min(min_r, body[kr].v);
        dr = std::max(dr, step_right());
      }
    }
    return bound;
  }

  // The widest pair among slots c - w .. c + w (mod n on a ring, inside the line).
  std::size_t widest_near(std::size_t c, std::size_t w, double t) const {
    std::size_t best = c;
    double widest = -std::numeric_limits<double>::infinity();
    for (std::size_t d = 0; d <= 2 * w; ++d) {
      const std::size_t i = wrap(c + n() - w + d);
      if (!e_.ring_ && i >= n() - 1) continue;
      const double g = gap(i, t);
      if (g > widest) widest = g, best = i;
    }
    return best;
  }

  Window plan(double t_stop) {
    const double t = e_.now_;
    if (!v_known_) {
      v_min_ = e_.body_[0].v, v_max_ = v_min_;
      fold_velocities(0, n());
    }
    const double dv = v_max_ - v_min_;
    const std::size_t domains = std::max(min_domains, n() / domain_bodies);
    const std::size_t w = n() / domains / 8;
    std::vector<std::size_t> cuts;
    std::vector<double> bound;
    for (std::size_t k = e_.ring_ ? 0 : 1; k < domains; ++k) {
      const std::size_t c = widest_near(k * n() / domains, w, t);
      cuts.push_back(c);
      bound.push_back(cut_bound(c, t, dv));
    }
    std::vector<double> sorted = bound;
    std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
    const double keep = 0.25 * sorted[sorted.size() / 2];
    Window win;
    double lookahead = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < cuts.size(); ++k) {
      if (bound[k] < keep) continue;
      win.cuts.push_back(cuts[k]);
      lookahead = std::min(lookahead, bound[k]);
    }
    if (!e_.ring_) win.cuts.push_back(n() - 1);  // the line's last slot never fires
    std::sort(win.cuts.begin(), win.cuts.end());
    // Slot times: all of them the first time; then those of the last window's
    // cuts, the only ones not kept up to date (their bodies moved on both sides).
    if (slot_time_.empty()) {
      slot_time_.resize(n());
      for (std::size_t i = 0; i < n(); ++i) slot_time_[i] = e_.pair_time(i, t);
    }
    for (std::size_t c : last_cuts_) slot_time_[c] = e_.pair_time(c, t);
    last_cuts_ = win.cuts;
    win.end = t + lookahead;
    if (rate_ > 0) win.end = std::min(win.end, t + 4.0 * static_cast<double>(n()) / rate_);
    if (win.end >= t_stop) win.end = t_stop, win.last = true;
    return win;
  }

  // Widens [v_min_, v_max_] by the velocities of bodies lo .. hi - 1 (mod n), in
  // four independent chains of comparisons.
  void fold_velocities(std::size_t lo, std::size_t hi) {
    double lo4[4] = {v_min_, v_min_, v_min_, v_min_}, hi4[4] = {v_max_, v_max_, v_max_, v_max_};
    for (std::size_t i = lo; i < hi; ++i) {
      const double v = e_.body_[wrap(i)].v;
      lo4[i % 4] = std::min(lo4[i % 4], v);
      hi4[i % 4] = std::max(hi4[i % 4], v);
    }
    v_min_ = std::min(std::min(lo4[0], lo4[1]), std::min(lo4[2], lo4[3]));
    v_max_ = std::max(std::max(hi4[0], hi4[1]), std::max(hi4[2], hi4[3]));
  }

  // Loads the memory of the domain to be started next into the second-level
  // cache a few lines at a time, while other domains run: its bodies and slot
  // times then arrive without a stall.
  struct Prefetcher {
    std::size_t body = 0, body_end = 0;  // body indices, unwrapped
    std::size_t slot = 0, slot_end = 0;
  };
  void aim(Prefetcher& p, const Window& w, std::size_t d) const {
    p = {};
    if (d >= w.cuts.size()) return;
    const std::size_t lo = w.cuts[d] + 1;
    const std::size_t hi = d + 1 < w.cuts.size() ? w.cuts[d + 1] : w.cuts[0] + n();
    p = {lo, hi + 1, lo, hi};
  }
  void advance(Prefetcher& p) const {
    constexpr std::size_t bodies_per_line = 64 / sizeof(e_.body_[0]) + 1;  // overlapping: every line hit
    constexpr std::size_t slots_per_line = 64 / sizeof(double);
    for (int k = 0; k < 2 && p.body < p.body_end; ++k, p.body += bodies_per_line - 1)
      prefetch_line_l2(&e_.body_[wrap(p.body)]);
    if (p.slot < p.slot_end) prefetch_line_l2(&slot_time_[wrap(p.slot)]), p.slot += slots_per_line;
  }

  // Domain d of w: the bodies after cut d up to cut d + 1; its pairs get local slots.
  void start(Stream& s, const Window& w, std::size_t d) {
    const std::size_t lo = w.cuts[d] + 1;
    const std::size_t hi = d + 1 < w.cuts.size() ? w.cuts[d + 1] : w.cuts[0] + n();
    s.base = wrap(lo);
    s.now = e_.now_;
    s.frozen = 0;
    s.busy = hi > lo;
    if (!s.busy && refold_) fold_velocities(lo, lo + 1);
    if (!s.busy) return;
    s.tree.assign(hi - lo, [&](std::size_t k) { return slot_time_[wrap(s.base + k)]; });
  }
  // Domain s is done: its slot times go back to slot_time_.
  void finish(const Stream& s) {
    for (std::size_t k = 0; k < s.tree.size(); ++k) slot_time_[wrap(s.base + k)] = s.tree.time(k);
    if (refold_) fold_velocities(s.base, s.base + s.tree.size() + 1);  // the domain's bodies, in cache
  }

  // The domain's next collision if it falls in the window; false when done.
  bool step(Stream& s, const Window& w) {
    const double t = s.tree.top_time();
    if (!(t < w.end || (w.last && t == w.end))) return false;
    const std::size_t k = s.tree.top();
    const std::size_t m = s.tree.size();
    const std::size_t i = wrap(s.base + k);
    const std::size_t j = e_.right(i);  // an internal pair: never none
    s.frozen = t == s.now ? s.frozen + 1 : 0;
    s.now = t;
    ++s.count[e_.collide_equal(i, j, t, s.dissipated, s.last_x)];
    if (k > 0) s.tree.set(k - 1, e_.contact_time(e_.left(i), i, t));  // pair (i - 1, i), inside the domain
    s.tree.set(k, EventTree::never);                                  // i and j separate
    if (k + 1 < m) s.tree.set(k + 1, e_.contact_time(j, e_.right(j), t));  // pair (j, j + 1), inside
    s.tree.refresh_range(k > 0 ? k - 1 : k, k + 1 < m ? k + 1 : k);
    return true;
  }

  // Runs every domain of w to its end; true on a rounding stall (then the engine
  // holds that domain's time and place). Sets halt when watch asks to stop; the
  // window is finished first, so that the state stays consistent. An abort
  // request (core/interrupt.hpp) throws Interrupted at once: the run is discarded.
  template <class Watch>
  bool run_window(const Window& w, Watch& watch, bool& halt) {
    std::size_t next = 0;
    // The velocities at the window's end, for the next window's bound: gathered
    // domain by domain while their bodies are in cache, every 8th window (the
    // range only shrinks, so an older one is a valid, looser bound).
    refold_ = ++windows_ % 8 == 0 || !v_known_;
    if (refold_) {
      v_min_ = std::numeric_limits<double>::infinity();
      v_max_ = -v_min_;
    }
    v_known_ = true;
    for (Stream& s : streams_) {
      s.count = {};
      s.dissipated = 0;
      s.busy = false;
      while (!s.busy && next < w.cuts.size()) start(s, w, next++);
    }
    Prefetcher ahead;
    aim(ahead, w, next);
    const std::uint64_t before = e_.count_[3];
    std::uint64_t done = 0, next_check = Engine::check_every;
    for (bool any = true; any;) {
      any = false;
      for (Stream& s : streams_) {
        if (!s.busy) continue;
        any = true;
        if (step(s, w)) {
          ++done;
          if (s.frozen >= Engine::frozen_limit) return stalled(s);
          continue;
        }
        s.busy = false;
        finish(s);
        while (!s.busy && next < w.cuts.size()) start(s, w, next++);
        aim(ahead, w, next);
      }
      advance(ahead);
      if (done >= next_check) {
        next_check += Engine::check_every;
        throw_if_aborted();  // an abort discards the run: its window need not be finished
        if (!halt && !watch(e_.now_, before + done)) halt = true;
      }
    }
    for (Stream& s : streams_) add_counts(s);
    const double span = w.end - e_.now_;
    if (span > 0 && !w.last) rate_ = static_cast<double>(done) / span;
    return false;
  }

  void add_counts(const Stream& s) {
    e_.count_[0] += s.count[0];
    e_.count_[1] += s.count[1];
    e_.count_[3] += s.count[0] + s.count[1];
    e_.dissipated_ += s.dissipated;
  }

  bool stalled(const Stream& s) {
    v_known_ = false;
    for (const Stream& other : streams_) add_counts(other);
    e_.now_ = s.now;
    e_.last_x_ = s.last_x;
    return true;
  }

  Engine& e_;
  std::array<Stream, 2> streams_;
  std::vector<double> slot_time_;       // contact time of every pair slot (8 bytes per body)
  std::vector<std::size_t> last_cuts_;  // the cuts of the last window
  double rate_ = 0;                     // collisions per unit time in the last full window
  double v_min_ = 0, v_max_ = 0;        // contains the velocities at now()
  bool v_known_ = false;
  bool refold_ = false;  // this window gathers the range anew
  std::uint64_t windows_ = 0;
  int thin_ = 0;         // consecutive thin windows
  bool global_ = false;  // continued on the global queue
};

}  // namespace shockgas::particles::detail
