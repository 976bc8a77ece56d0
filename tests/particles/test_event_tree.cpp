// The tournament tree against a brute-force minimum.
#include <gtest/gtest.h>

#include <algorithm>

#include "event_tree.hpp"
#include "shockgas/core/random.hpp"

namespace shockgas::particles {
namespace {

// Sizes around the block size and powers of two (leaves at two depths).
TEST(EventTree, TopIsTheMinimumAfterRandomUpdates) {
  // The last size is large enough for the hinting climb (EventTree::hint_slots).
  for (std::size_t n : {1u, 2u, 3u, 7u, 8u, 9u, 17u, 100u, 1000u, 1025u, (1u << 18) + 3u}) {
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

}  // namespace
}  // namespace shockgas::particles
