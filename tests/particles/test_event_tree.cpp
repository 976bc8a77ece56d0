// The tournament tree against a brute-force minimum.
#include <gtest/gtest.h>

#include <algorithm>

#include "shockgas/core/random.hpp"
#include "shockgas/particles/event_tree.hpp"

namespace shockgas::particles {
namespace {

// Sizes around the block size and powers of two (leaves at two depths).
TEST(EventTree, TopIsTheMinimumAfterRandomUpdates) {
  for (std::size_t n : {1u, 2u, 3u, 7u, 8u, 9u, 17u, 100u, 1000u, 1025u}) {
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
        tree.refresh_range(lo, hi);
      } else {
        for (std::size_t i = lo; i <= hi; ++i) tree.refresh_path(i);
      }
      const double best = *std::min_element(t.begin(), t.end());
      ASSERT_EQ(tree.top_time(), best);  // exact: the tree only copies values
      ASSERT_EQ(t[tree.top()], best);
    }
  }
}

}  // namespace
}  // namespace shockgas::particles
