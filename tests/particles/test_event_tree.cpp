// The tournament tree against a brute-force minimum.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>

#include "shockgas/core/random.hpp"
#include "shockgas/particles/event_tree.hpp"

namespace shockgas::particles {
namespace {

// Sizes around the block size and powers of two (leaves at two depths).
TEST(EventTree, TopIsTheMinimumAfterRandomUpdates) {
  // The last size is large enough for the hinting climb (EventTree::hint_slots).
  for (std::size_t n : {1u, 2u, 3u, 7u, 8u, 9u, 15u, 16u, 17u, 33u, 100u, 1000u, 1025u, (1u << 18) + 3u}) {
    SCOPED_TRACE(n);
    Rng rng(n);
    EventTree tree(n);
    std::vector<double> t(n, EventTree::never);
    EXPECT_EQ(tree.top_time(), EventTree::never);
    for (int step = 0; step < 5000; ++step) {
      // One to three adjacent slots, as after a collision; sometimes +inf.
      const std::size_t lo = static_cast<std::size_t>(rng.uniform() * n);
      const std::size_t hi = std::min(n - 1, lo + static_cast<std::size_t>(rng.uniform() * 3));
      for (std::size_t i = lo; i <= hi; ++i) {
        t[i] = rng.uniform() < 0.1 ? EventTree::never : rng.uniform(0.0, 100.0);
        tree.set(i, t[i]);
      }
      if (step % 2) {
        tree.refresh(lo, hi);
      } else {
        for (std::size_t i = lo; i <= hi; ++i) tree.refresh_path(i);
      }
      if (n > 5000 && step % 256) continue;  // the brute-force minimum dominates at this size
      const double best = *std::min_element(t.begin(), t.end());
      ASSERT_EQ(tree.top_time(), best);  // exact: the tree only copies values
      ASSERT_EQ(t[tree.top()], best);
      ASSERT_LT(tree.hint(),
                (n + EventTree::block - 1) / EventTree::block * EventTree::block);  // a slot of some block
    }
  }
}

// The prefetch hint: after refreshing one slot's path, the earliest time outside
// that slot's block (the runner-up of the subtrees the path passes).
TEST(EventTree, HintIsTheRunnerUpAlongTheRefreshedPath) {
  const std::size_t n = EventTree::hint_slots + 100;
  EventTree tree(n);
  ASSERT_TRUE(tree.hinting());
  const std::size_t far = 12345, near = n - 7, other = 200000;
  tree.set(far, 5.0);
  tree.set(other, 6.0);
  tree.rebuild();
  tree.set(near, 1.0);
  tree.refresh_path(near);
  EXPECT_EQ(tree.top(), near);
  EXPECT_EQ(tree.hint(), far);
  EXPECT_FALSE(EventTree(1000).hinting());  // small trees: no hint work in the climb
}

// A bounce's three slots at once (replace_three: with AVX-512, merged into their
// block's lines in registers) leave the times and every node exactly as three
// set() calls and refresh(p, p + 2) do (the block minimum of the portable
// build), on runs that start and end inside a block shared with a neighbouring
// run (whose slots it must not write), or on a block boundary beside one, and
// wrap past the ring's last slot. Times from a few
// values, so that ties are common and the lane a minimum is taken from shows.
TEST(EventTree, ReplaceThreeIsSetAndRefresh) {
  struct Run {
    std::size_t n, first, last;
  };
  for (const Run run : {Run{1000, 0, 999}, Run{1003, 5, 1001}, Run{1003, 13, 15}, Run{1003, 21, 46},
                        Run{1003, 32, 95}, Run{1000, 990, 20}, Run{4099, 3, 4094}, Run{4099, 30, 4081}}) {
    SCOPED_TRACE(testing::Message() << run.n << " " << run.first << " " << run.last);
    Rng rng(run.n + run.first);
    SlotTimes fast, plain;
    fast.reset(run.n), plain.reset(run.n);
    const double outside = -1.0;  // the neighbours' slots: never written by the run
    const std::size_t length = (run.last + run.n - run.first) % run.n + 1;
    for (std::size_t s = 0; s < run.n; ++s) fast[s] = plain[s] = outside;
    for (std::size_t k = 0; k < length; ++k)
      fast[(run.first + k) % run.n] = plain[(run.first + k) % run.n] = 7.0;
    EventTree a, b;
    a.attach(fast, run.first, run.last);
    b.attach(plain, run.first, run.last);
    for (int step = 0; step < 20000; ++step) {
      const std::size_t p = (run.first + static_cast<std::size_t>(rng.uniform() * (length - 2))) % run.n;
      const double tp = std::floor(rng.uniform(0.0, 8.0)), tj = rng.uniform() < 0.2 ? EventTree::never : 3.0;
      a.replace_three(p, tp, tj);
      const std::size_t i = (p + 1) % run.n, j = (p + 2) % run.n;
      b.set(p, tp), b.set(i, EventTree::never), b.set(j, tj);
      b.refresh(p, j);
      ASSERT_EQ(a.top(), b.top());
      ASSERT_EQ(a.top_time(), b.top_time());
    }
    for (std::size_t k = 0; k < a.node_count(); ++k) {
      ASSERT_EQ(a.node_keys()[k], b.node_keys()[k]) << k;
      ASSERT_EQ(a.node_slots()[k], b.node_slots()[k]) << k;
    }
    for (std::size_t s = 0; s < run.n; ++s)
      ASSERT_EQ(std::bit_cast<std::uint64_t>(fast[s]), std::bit_cast<std::uint64_t>(plain[s])) << s;
  }
}

// A bounce across the ring's end (slots N - 2, N - 1, 0) where the last block
// holds slot N - 1 alone (N = 1 mod 16): its three slots span three blocks,
// and every one must be refreshed. refresh(N - 2, 0) left the middle block's
// old winner on top, and the windowed engine met the same pair again at the
// same time until the run stopped as a stall (found from outside: every ring
// of N = 1 mod 16, 1025 to 100001, stopped early with exit 0). The top is the
// minimum of the run's times after every bounce, on whole rings and on runs
// that wrap, for N = 1 mod 16 and, as a control, N that is not.
TEST(EventTree, ABounceAcrossTheRingsEndKeepsTheTopTheMinimum) {
  struct Run {
    std::size_t n, first, last;
  };
  for (const Run run : {Run{1009, 0, 1008}, Run{1009, 960, 40}, Run{4097, 4000, 100}, Run{33, 0, 32},
                        Run{1000, 0, 999}, Run{1000, 950, 30}}) {
    SCOPED_TRACE(testing::Message() << run.n << " " << run.first << " " << run.last);
    Rng rng(run.n + run.first);
    SlotTimes times;
    times.reset(run.n);
    const std::size_t length = (run.last + run.n - run.first) % run.n + 1;
    for (std::size_t k = 0; k < length; ++k) times[(run.first + k) % run.n] = rng.uniform(1.0, 2.0);
    EventTree tree;
    tree.attach(times, run.first, run.last);
    for (int step = 0; step < 4000; ++step) {
      // Half the bounces at the ring's end, p = N - 2 or N - 1; the rest anywhere in the run.
      const std::size_t end = run.n - 2 + static_cast<std::size_t>(rng.uniform() < 0.5);
      const std::size_t p =
          rng.uniform() < 0.5 && (run.first == 0 || run.last < run.first)
              ? end
              : (run.first + static_cast<std::size_t>(rng.uniform() * (length - 2))) % run.n;
      tree.replace_three(p, rng.uniform(0.0, 3.0), rng.uniform(0.0, 3.0));
      double least = EventTree::never;
      for (std::size_t k = 0; k < length; ++k) least = std::min(least, times[(run.first + k) % run.n]);
      ASSERT_EQ(tree.top_time(), least) << "step " << step << ", p = " << p;
      ASSERT_EQ(times[tree.top()], least);
    }
  }
}

}  // namespace
}  // namespace shockgas::particles
