#pragma once
// The saved state of the engine and of the window scheduler (private to
// particles/; the order of the bytes is state_io.hpp's contract): everything
// their future depends on, as it is in memory.
//
// Engine: the bodies (x at their own time t, v; masses and links if Linked),
// the pair times, the global queue's nodes if it is in use, the time, the
// stall counters, the counts and the energy. Scheduler: whether a plan is open
// and its start, horizon and cuts; each domain's bodies, tree range, time,
// stall counter and its tree's nodes; the rate estimates, the velocity range,
// the plan counter and thin-plan counter, and the global/window choice.
#include <cstdint>
#include <utility>

#include "shockgas/particles/event_engine.hpp"
#include "shockgas/particles/state_io.hpp"
#include "shockgas/particles/window_scheduler.hpp"

namespace shockgas::particles::detail {

namespace state_tags {
inline constexpr std::uint64_t engine = 0x31656e69676e45ull;     // "Engine1"
inline constexpr std::uint64_t scheduler = 0x31776f646e6957ull;  // "Window1"
}  // namespace state_tags

// The nodes of a tree as they are (2 x nb keys and slots) and its hint.
inline void StateIo::put_nodes(RunStateWriter& out, const EventTree& t) {
  put<std::uint64_t>(out, t.node_count());
  out.write(t.key_, t.node_count() * sizeof(EventTree::Key));
  out.write(t.win_, t.node_count() * sizeof(std::uint32_t));
  put(out, t.hint_);
}
inline void StateIo::get_nodes(RunStateReader& in, EventTree& t) {
  if (get_count(in, sizeof(EventTree::Key) + sizeof(std::uint32_t), "a tree") != t.node_count())
    throw RunError("a saved run state: a tree's size differs from the run it is resumed in");
  in.read(t.key_, t.node_count() * sizeof(EventTree::Key));
  in.read(t.win_, t.node_count() * sizeof(std::uint32_t));
  t.hint_ = get<std::uint32_t>(in);
}

template <bool Linked>
void StateIo::save(const EventEngine<Linked>& e, RunStateWriter& out) {
  put(out, state_tags::engine);
  put<std::uint64_t>(out, Linked);
  put<std::uint64_t>(out, e.n_);
  put(out, e.L_);
  put(out, e.ring_);
  put<std::uint64_t>(out, e.alive_);
  put(out, e.m0_);
  put_vector(out, e.body_);
  put<std::uint64_t>(out, e.slot_.blocks() * SlotTimes::block);
  out.write(e.slot_.block_data(0), e.slot_.blocks() * SlotTimes::block * sizeof(double));
  if constexpr (Linked) put_vector(out, e.mass_), put_vector(out, e.next_), put_vector(out, e.prev_);
  put(out, e.now_), put(out, e.window_start_), put(out, e.stall_);
  put(out, e.last_x_), put(out, e.dissipated_), put(out, e.count_);
  const bool queue = e.tree_.node_count() > 0;  // the global queue is in use
  put(out, queue);
  if (queue) put_nodes(out, e.tree_);
}

template <bool Linked>
void StateIo::restore(EventEngine<Linked>& e, RunStateReader& in) {
  expect(in, state_tags::engine, "engine tag");
  expect<std::uint64_t>(in, Linked, "engine layout (masses and merges)");
  expect<std::uint64_t>(in, e.n_, "number of bodies");
  expect(in, e.L_, "length");
  expect(in, e.ring_, "geometry");
  e.alive_ = get<std::uint64_t>(in);
  e.m0_ = get<double>(in);
  e.body_.resize(e.n_);
  get_into(in, e.body_, "the bodies");
  e.slot_.reset(e.n_);
  if (get_count(in, sizeof(double), "the pair times") != e.slot_.blocks() * SlotTimes::block)
    throw RunError("a saved run state: its pair times do not fit the run it is resumed in");
  in.read(e.slot_.data(), e.slot_.blocks() * SlotTimes::block * sizeof(double));
  if constexpr (Linked) {
    e.mass_.resize(e.n_), e.next_.resize(e.n_), e.prev_.resize(e.n_);
    get_into(in, e.mass_, "the masses"), get_into(in, e.next_, "the links"),
        get_into(in, e.prev_, "the links");
  }
  e.now_ = get<double>(in), e.window_start_ = get<double>(in), e.stall_ = get<int>(in);
  e.last_x_ = get<double>(in), e.dissipated_ = get<double>(in);
  e.count_ = get<decltype(e.count_)>(in);
  if (get<bool>(in)) {
    e.use_global_queue();
    get_nodes(in, e.tree_);
  }
}

template <bool Linked>
void StateIo::save(const WindowScheduler<Linked>& s, RunStateWriter& out) {
  put(out, state_tags::scheduler);
  put(out, s.planned_), put(out, s.plan_start_), put(out, s.horizon_), put(out, s.plan_collisions_);
  put(out, s.plans_), put(out, s.rate_), put(out, s.last_rate_), put(out, s.v_min_), put(out, s.v_max_);
  put(out, s.v_known_), put(out, s.thin_), put(out, s.global_);
  put_text(out, s.why_global_);
  put_vector(out, s.cuts_);
  if (!s.planned_) return;
  put<std::uint64_t>(out, s.domains_.size());
  for (const Domain& d : s.domains_) {
    put(out, d.head), put(out, d.tail), put(out, d.empty);
    put(out, d.tree.last());  // the range its tree was built over: head .. last (tail moves on merges)
    put(out, d.now), put(out, d.last_x), put(out, d.frozen), put(out, d.stalled);
    put(out, d.count), put(out, d.dissipated);
  }
  put_vector(out, s.key_);
  put_vector(out, s.win_);
}

// The domains are rebuilt over the saved ranges, then their nodes overwritten
// with the saved ones.
template <bool Linked>
void StateIo::restore(WindowScheduler<Linked>& s, RunStateReader& in) {
  expect(in, state_tags::scheduler, "scheduler tag");
  s.planned_ = get<bool>(in), s.plan_start_ = get<double>(in), s.horizon_ = get<double>(in);
  s.plan_collisions_ = get<std::uint64_t>(in);
  s.plans_ = get<std::uint64_t>(in), s.rate_ = get<double>(in), s.last_rate_ = get<double>(in);
  s.v_min_ = get<double>(in), s.v_max_ = get<double>(in);
  s.v_known_ = get<bool>(in), s.thin_ = get<int>(in), s.global_ = get<bool>(in);
  s.why_global_ = get_text(in, "the reason for the global queue");
  get_vector(in, s.cuts_, "the cuts");
  if (!s.planned_) return;
  s.domains_.resize(get_count(in, 8 * sizeof(double), "the domains"));
  std::vector<std::size_t> tails(s.domains_.size());
  const std::size_t n = s.n();
  for (std::size_t k = 0; k < s.domains_.size(); ++k) {
    Domain& d = s.domains_[k];
    d.head = get<std::size_t>(in), tails[k] = get<std::size_t>(in), d.empty = get<bool>(in);
    const auto last = get<std::size_t>(in);
    if (d.head >= n || tails[k] >= n || last >= n)
      throw RunError("a saved run state: a domain lies outside the bodies of the run it is resumed in");
    d.tail = last + 1 == n ? 0 : last + 1;  // the tail the tree was built for
    d.now = get<double>(in), d.last_x = get<double>(in), d.frozen = get<int>(in), d.stalled = get<bool>(in);
    d.count = get<decltype(d.count)>(in), d.dissipated = get<double>(in);
  }
  s.attach_trees();
  for (std::size_t k = 0; k < s.domains_.size(); ++k) s.domains_[k].tail = tails[k];
  get_into(in, s.key_, "the domains' trees");
  get_into(in, s.win_, "the domains' trees");
}

}  // namespace shockgas::particles::detail
