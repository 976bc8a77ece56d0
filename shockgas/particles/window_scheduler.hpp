#pragma once
// Runs the engine in time windows over stretches of the chain (domains), on a
// team of threads: the same collisions as the global queue, with local memory
// access, and a result that does not depend on the number of threads.
//
// Why. The global queue takes the events in time order, and the next event lies
// anywhere on the ring, so at N = 10^6 nearly every event misses the caches. And
// one event is one serial chain (contact, division, tree climb): the core idles
// between its steps.
//
// A plan (window_plan.hpp for the cuts and their bounds) holds from its start T
// to its horizon T_w = T + the smallest bound of its cuts, and for at most
// plan_collisions(N) collisions at the last plan's rate. Each domain (the bodies between
// two cuts) has a tournament tree of its own over its pair slots, small enough
// for a core's caches; the trees live as long as the plan. run_until(t) runs
// every domain to min(t, T_w) (a sub-window: snapshots and whole-state samples
// end one, the domains and their trees stay); at T_w the next plan cuts
// elsewhere. run_sampled runs through many sample times in one sub-window: each
// domain stops at each of them to measure its part of the sample
// (domain_sampler.hpp) while its bodies are in cache, and goes on; the parts are
// combined in domain order after the sub-window. So a short run does not stream
// the whole state in again for every sample, neither for its collisions nor for
// its observables.
//
// Exactness. The contact times are computed by the same function from the same
// states as in the global queue, so a domain sees the same collisions in the same
// order, and the final state is the same to the last bit (up to the order of
// collisions of overlapping pairs at exactly the same time: test
// WindowScheduler.*).
//
// Threads. Within a sub-window the domains are independent: each member of the
// team claims domains by index and runs two at a time, interleaved event by event
// so that their serial chains overlap in the core. Nothing the schedule decides
// depends on the team: the cuts and horizons are functions of the state; each
// domain keeps its own collision counts and dissipated energy, added to the
// engine's in domain order at the end of every sub-window (and of every sample
// taken in parts: the same sums in the same order); a collision limit is
// checked there, on the exact total; a rounding stall is reported for the first
// stalled domain in domain order after the sub-window ends.
//
// If no cut can open, or 8 plans in a row hold fewer than N/64 collisions, the
// run continues on the global queue (one thread).
//
// Saves (run_state.hpp) are taken where the watch is asked, after a sub-window;
// on a checkpoint request a sub-window without samples is also cut short and
// saved as it is (a plan at N = 10^8 runs for tens of seconds).
#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "shockgas/core/interrupt.hpp"
#include "shockgas/core/thread_team.hpp"
#include "shockgas/particles/domain_prefetcher.hpp"
#include "shockgas/particles/domain_sampler.hpp"
#include "shockgas/particles/event_engine.hpp"
#include "shockgas/particles/window_domain.hpp"
#include "shockgas/particles/window_plan.hpp"

namespace shockgas::particles::detail {

template <bool Linked>
class WindowScheduler {
 public:
  using Engine = EventEngine<Linked>;
  using Planner = WindowPlanner<Linked>;
  static constexpr std::size_t none = Engine::none;
  // A plan expected to hold at least this many collisions per body (at the last
  // plan's rate) is cut finer (WindowPlanner::refine), whose scan of the chain
  // costs about what the smaller trees save per collision (docs/performance.md,
  // "Finer cuts inside a plan"). Plans of fewer keep the coarse domains, and with
  // them the few parts per sample of short, densely sampled runs.
  static constexpr double refine_collisions_per_body = 3;

  // threads: members of the team that runs the domains (>= 1); refine_from: the
  // collisions per body from which a plan is cut finer (refine_collisions_per_body;
  // 0 refines every plan).
  WindowScheduler(Engine& e, std::size_t threads, double refine_from = refine_collisions_per_body)
      : e_(e), stepper_(e), planner_(e), team_(threads), refine_from_(refine_from) {}

  // As Engine::run_until: processes every collision at time <= t_stop.
  template <class Watch>
  EngineStop run_until(double t_stop, Watch& watch) {
    if (const std::optional<EngineStop> s = run_windows(t_stop, watch, nullptr)) return *s;
    return e_.run_until(t_stop, watch);
  }

  // Runs to the last time of the batch, and each domain measures its part of
  // every sample of the batch when it reaches the sample's time; the batch gets
  // the parts in domain order, with the engine's counts at that time. Returns
  // early, with samples pending, when the run leaves the windows for the global
  // queue (then they must be taken from the state there).
  template <class Watch>
  EngineStop run_sampled(double t_stop, Watch& watch, SampleBatch& batch) {
    return run_windows(t_stop, watch, &batch).value_or(EngineStop::reached);
  }

  bool on_global_queue() const { return global_; }
  // Why the run left the windows for the global queue ("" while it has not).
  const std::string& why_global() const { return why_global_; }
  std::size_t threads() const { return team_.size(); }

 private:
  friend struct StateIo;
  std::size_t n() const { return e_.n_; }

  // Sub-windows up to t_stop (and the batch's samples on the way); nullopt when
  // the run continues on the global queue.
  template <class Watch>
  std::optional<EngineStop> run_windows(double t_stop, Watch& watch, SampleBatch* batch) {
    while (!global_) {
      if (!planned_ && !start_plan(watch.collisions_left(e_.count_[3]))) break;
      const bool to_stop = t_stop <= horizon_;  // then collisions at exactly t_stop are included
      const double end = to_stop ? t_stop : horizon_;
      bool halt = false;
      const std::uint64_t before = e_.count_[3];
      const double from = e_.now_;
      if (batch) batch->open(end, to_stop, domains_.size(), team_.size());
      run_domains(end, to_stop, watch, halt, batch);
      // Cut short: the domains are independent until the sub-window's end, so
      // each one's progress (its tree, time, counts and energy not yet settled)
      // is a state to go on from; a resumed run runs the same sub-window on.
      if (cut_short_.exchange(false)) watch.save_and_stop(e_.now_);
      if (batch) deliver_samples(*batch);
      settle();
      if (end > from) last_rate_ = static_cast<double>(e_.count_[3] - before) / (end - from);
      if (const Domain* d = first_stalled()) {
        e_.now_ = d->now;
        e_.last_x_ = d->last_x;
        return EngineStop::stall;
      }
      e_.now_ = std::max(e_.now_, end);
      if (!to_stop || t_stop == horizon_) end_plan();
      // A safe point: the watch may save the state here, also when it is to halt.
      const bool go_on = watch(e_.now_, e_.count_[3]);
      if (halt || !go_on) return EngineStop::halted;
      if (to_stop) return EngineStop::reached;
    }
    return std::nullopt;
  }

  // The collisions a plan holds at most (at the last plan's rate): 4 per body,
  // and at least 2^24. Each plan re-cuts the chain, rebuilds the domains' trees
  // and loads every domain into a cache again, so a plan of a small system
  // should hold more than a few collisions per body (docs/performance.md, "Two
  // threads on one realization"). The stops that wait for a sub-window's end
  // (periodic saves, the wall-clock limit, a checkpoint request in a sub-window
  // with samples) then wait at most about 0.6 s of one core below N = 2^22, and
  // as long as before above it.
  static double plan_collisions(std::size_t n) { return std::max(4.0 * static_cast<double>(n), 16777216.0); }

  // Cuts the chain at now(); false when no cut can open (then the run goes on
  // on the global queue). A plan holds no more than the collisions left to
  // the limit (but at least about N: a plan thinner than N / 64 counts as thin).
  bool start_plan(std::uint64_t collisions_left) {
    const double t = e_.now_;
    if (!v_known_ || ++plans_ % 8 == 0) gather_velocity_range();
    const double lookahead = planner_.choose(t, v_max_ - v_min_, team_, cuts_);
    horizon_ = t + lookahead;
    const double budget = std::min(plan_collisions(n()),
                                   std::max(static_cast<double>(collisions_left), static_cast<double>(n())));
    if (rate_ > 0) horizon_ = std::min(horizon_, t + budget / rate_);
    if (!(horizon_ > t)) {
      why_global_ = "no cut could open (the gas is in contact everywhere)";
      switch_to_global();
      return false;
    }
    if (rate_ * (horizon_ - t) >= refine_from_ * static_cast<double>(n()))
      planner_.refine(t, v_max_ - v_min_, horizon_ - t, team_, cuts_);
    make_domains();
    planned_ = true;
    plan_start_ = t;
    plan_collisions_ = e_.count_[3];
    return true;
  }

  // The velocity range at now(), in parallel slices; the range only shrinks, so
  // an older one is a valid, looser bound (gathered every 8th plan).
  void gather_velocity_range() {
    const std::size_t parts = team_.size();
    std::vector<double> lo(parts, std::numeric_limits<double>::infinity()), hi(parts, -lo[0]);
    team_.run([&](std::size_t k) {
      planner_.fold_velocities(k * n() / parts, (k + 1) * n() / parts, lo[k], hi[k]);
    });
    v_min_ = *std::min_element(lo.begin(), lo.end());
    v_max_ = *std::max_element(hi.begin(), hi.end());
    v_known_ = true;
  }

  // The domains between the cuts, each with its tree over its pair slots.
  void make_domains() {
    std::vector<std::pair<std::size_t, std::size_t>> spans;  // head, tail
    if (e_.ring_) {
      for (std::size_t d = 0; d < cuts_.size(); ++d)
        spans.push_back({e_.right(cuts_[d]), cuts_[(d + 1) % cuts_.size()]});
    } else {
      std::size_t head = 0;
      for (std::size_t c : cuts_) spans.push_back({head, c}), head = e_.right(c);
      spans.push_back({head, last_live()});
    }
    domains_.resize(spans.size());
    for (std::size_t d = 0; d < spans.size(); ++d) {
      Domain& dom = domains_[d];
      dom.head = spans[d].first;
      dom.tail = spans[d].second;
      dom.empty = dom.head == dom.tail;
      dom.now = e_.now_;
      dom.frozen = 0;
      dom.stalled = false;
    }
    attach_trees();
  }
  // Each domain's tree over its pair slots head .. before(tail), nodes in the arenas.
  void attach_trees() {
    std::vector<std::size_t> offset(domains_.size() + 1, 0);
    for (std::size_t d = 0; d < domains_.size(); ++d) {
      const Domain& dom = domains_[d];
      const std::size_t blocks = dom.empty ? 0 : EventTree::blocks_of(e_.slot_, dom.head, before(dom.tail));
      offset[d + 1] = offset[d] + padded_nodes(blocks);
    }
    // The old nodes are not needed: a larger arena replaces the old one instead
    // of being copied from it (which would hold both at once), with room to grow.
    if (offset.back() > key_.capacity()) {
      key_ = decltype(key_)(), win_ = decltype(win_)();
      key_.reserve(offset.back() + offset.back() / 16), win_.reserve(offset.back() + offset.back() / 16);
    }
    key_.resize(offset.back());
    win_.resize(offset.back());
    std::atomic<std::size_t> next{0};
    team_.run([&](std::size_t) {
      for (std::size_t d = next++; d < domains_.size(); d = next++) {
        Domain& dom = domains_[d];
        if (!dom.empty)
          dom.tree.attach(e_.slot_, dom.head, before(dom.tail), key_.data() + offset[d],
                          win_.data() + offset[d]);
      }
    });
  }
  // A domain's nodes rounded up to whole pairs of cache lines of keys: the root
  // of one domain, written at every collision, then shares no line with the
  // leaves of the domain before it, which another member may be running.
  static std::size_t padded_nodes(std::size_t blocks) {
    constexpr std::size_t unit = 128 / sizeof(EventTree::Key);
    return (EventTree::nodes(blocks) + unit - 1) / unit * unit;
  }
  std::size_t before(std::size_t i) const { return i == 0 ? n() - 1 : i - 1; }
  std::size_t last_live() const {
    std::size_t i = n() - 1;
    while (!e_.live(i)) --i;
    return i;
  }

  // The plan reached its horizon: the cut slots, not kept up to date while it
  // ran (their bodies moved on both sides), are recomputed.
  void end_plan() {
    for (const Domain& d : domains_) e_.slot_[d.tail] = e_.pair_time(d.tail, e_.now_);
    planned_ = false;
    const std::uint64_t done = e_.count_[3] - plan_collisions_;
    rate_ = static_cast<double>(done) / (horizon_ - plan_start_);
    // Plans that stay thin (cuts barely open: a gas in contact everywhere) cost
    // O(N) each for a few collisions; the global queue is cheaper then.
    thin_ = done < n() / 64 ? thin_ + 1 : 0;
    if (thin_ >= 8) {
      why_global_ =
          "8 plans in a row held fewer than N/64 collisions (cuts barely open), where the global queue is "
          "cheaper";
      switch_to_global();
    }
  }
  void switch_to_global() {
    if (planned_) end_plan();
    global_ = true;
    // Their memory goes to the global tree.
    domains_ = decltype(domains_)();
    key_ = decltype(key_)();
    win_ = decltype(win_)();
    e_.use_global_queue();
  }

  // The domains' counts and energy into the engine's, in domain order.
  void settle() {
    for (Domain& d : domains_) {
      add_counts(d.count, d.dissipated);
      d.count = {};
      d.dissipated = 0;
    }
  }
  void add_counts(const std::array<std::uint64_t, 3>& count, double dissipated) {
    for (int k = 0; k < 3; ++k) e_.count_[k] += count[k], e_.count_[3] += count[k];
    e_.dissipated_ += dissipated;
    if constexpr (Linked) e_.alive_ -= count[2];
  }
  // The sub-window's samples in time order: the collisions up to each into the
  // engine's counts (in domain order, as settle), then the sample to the batch.
  void deliver_samples(SampleBatch& batch) {
    for (std::size_t k = 0; k < batch.count(); ++k) {
      for (std::size_t d = 0; d < domains_.size(); ++d)
        add_counts(batch.part(d, k).count, batch.part(d, k).dissipated);
      batch.deliver(k);
    }
    batch.close();
  }
  const Domain* first_stalled() const {
    for (const Domain& d : domains_)
      if (d.stalled) return &d;
    return nullptr;
  }

  // Every domain to `end` (inclusive: collisions at exactly end too), on the
  // team, each stopping on the way at the batch's samples of the sub-window to
  // take its part. Member 0 tells the watch about the time every so many steps;
  // halt is set when the watch asks to stop (the sub-window finishes first). On
  // an abort request (shockgas/core/interrupt.hpp) every member throws Interrupted within
  // check_every / 2 rounds of its own; the team rethrows it.
  template <class Watch>
  void run_domains(double end, bool inclusive, Watch& watch, bool& halt, SampleBatch* batch) {
    const double limit = inclusive ? end : std::nextafter(end, -std::numeric_limits<double>::infinity());
    const std::size_t samples = batch ? batch->count() : 0;
    for (Domain& d : domains_) d.sample = 0, d.limit = samples > 0 ? batch->time(0) : limit;
    std::optional<DomainSampler<Linked>> sampler;
    if (samples > 0) sampler.emplace(e_);
    // Takes the parts of the samples domain d has reached; whether it has a
    // collision before its next limit.
    auto ready = [&](Domain& d, std::size_t member) {
      for (;;) {
        if (d.stalled) return false;
        if (!d.empty && d.tree.top_time() <= d.limit) return true;
        if (d.sample == samples) return false;
        batch->take(*sampler, d, static_cast<std::size_t>(&d - domains_.data()), d.sample, member);
        d.limit = ++d.sample < samples ? batch->time(d.sample) : limit;
      }
    };
    const double domains = static_cast<double>(std::max<std::size_t>(domains_.size(), 1));
    const std::size_t lines_per_round = DomainPrefetcher::lines_per_round(
        static_cast<double>(n()) / domains, sizeof(typename Engine::Body) + sizeof(double),
        last_rate_ * (end - e_.now_) / domains);
    // On a line of its own: the members claim through it, and the lines around
    // it on member 0's stack are read by all.
    alignas(128) std::atomic<std::size_t> next{0};
    team_.run([&](std::size_t member) {
      const std::size_t lines = lines_per_round;  // a copy in the member's own frame
      auto claim = [&]() -> Domain* {
        for (std::size_t d = next++; d < domains_.size(); d = next++)
          if (ready(domains_[d], member)) return &domains_[d];
        return nullptr;
      };
      // The domain after the running ones is claimed early, and its memory loaded
      // while they run.
      Domain* ahead = claim();
      DomainPrefetcher prefetch;
      auto take = [&]() {
        Domain* d = ahead;
        ahead = claim();
        prefetch.aim(ahead, e_.body_.data(), &e_.slot_[0], n());
        return d;
      };
      // Two domains at once, a step of each per round (step() is false when a
      // domain reached its limit or stalled).
      std::array<Domain*, 2> s{};
      s[0] = take(), s[1] = take();
      for (std::uint64_t round = 1; s[0] || s[1]; ++round) {
        if (s[0] && s[1]) [[likely]] {
          const bool a = stepper_.step(*s[0], s[0]->limit), b = stepper_.step(*s[1], s[1]->limit);
          if (!a) [[unlikely]]
            if (!ready(*s[0], member)) s[0] = take();
          if (!b) [[unlikely]]
            if (!ready(*s[1], member)) s[1] = take();
        } else {
          Domain*& one = s[0] ? s[0] : s[1];
          if (!stepper_.step(*one, one->limit) && !ready(*one, member)) one = take();
        }
        prefetch.advance(lines);
        if (round % (Engine::check_every / 2) == 0) [[unlikely]] {
          throw_if_aborted();  // every member: an abort leaves the sub-window unfinished
          if (member == 0 && !halt && !watch.tick(end)) {
            halt = true;
            // A checkpoint request to a run that saves, in a sub-window without
            // samples: every member stops where it is (run_windows saves).
            if (samples == 0 && watch.saves_on_request()) cut_short_.store(true, std::memory_order_relaxed);
          }
          if (cut_short_.load(std::memory_order_relaxed)) [[unlikely]]
            break;
        }
      }
    });
  }

  Engine& e_;
  DomainStepper<Linked> stepper_;
  Planner planner_;
  ThreadTeam team_;
  double refine_from_;
  std::vector<std::size_t> cuts_;                                       // of the current plan, ascending
  std::vector<Domain> domains_;                                         // of the current plan, in chain order
  std::vector<EventTree::Key, HugePageAllocator<EventTree::Key>> key_;  // the domains' tree nodes
  std::vector<std::uint32_t, HugePageAllocator<std::uint32_t>> win_;
  bool planned_ = false;
  double plan_start_ = 0, horizon_ = 0;
  std::uint64_t plan_collisions_ = 0;  // the engine's count when the plan started
  std::uint64_t plans_ = 0;
  double rate_ = 0;               // collisions per unit time in the last plan
  double last_rate_ = 0;          // the same in the last sub-window (for prefetching only)
  double v_min_ = 0, v_max_ = 0;  // contains the velocities at now()
  bool v_known_ = false;
  int thin_ = 0;         // consecutive thin plans
  bool global_ = false;  // continued on the global queue
  std::string why_global_;
  std::atomic<bool> cut_short_{false};  // the members stop inside the sub-window (run_domains)
};

}  // namespace shockgas::particles::detail
