#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <optional>

#include "shockgas/core/error.hpp"
#include "shockgas/core/random.hpp"
#include "shockgas/particles/cluster_finder.hpp"

namespace shockgas::particles {
namespace {

// Sums and positions below are of a handful of O(1) numbers: rounding of a few ulps.
constexpr double kRound = 1e-12;

TEST(ClusterFinder, LineGroupsCloseCoMovingRuns) {
  Bodies b;
  // A tight co-moving pair, a lone body, a tight triple.
  b.push_back(1.0, 0.50, 1);
  b.push_back(1.1, 0.51, 1);
  b.push_back(3.0, -0.2, 1);
  b.push_back(5.0, 0.30, 2);
  b.push_back(5.2, 0.30, 1);
  b.push_back(5.4, 0.31, 1);
  const auto k = find_clusters(b, 0.0, ClusterCriteria{0.5, 0.02});
  ASSERT_EQ(k.size(), 3u);
  EXPECT_EQ(k[0].first, 0u);
  EXPECT_EQ(k[0].count, 2u);
  EXPECT_NEAR(k[0].x, 1.05, kRound);
  EXPECT_NEAR(k[0].v, 0.505, kRound);
  EXPECT_EQ(k[1].count, 1u);
  EXPECT_EQ(k[2].first, 3u);
  EXPECT_EQ(k[2].count, 3u);
  EXPECT_NEAR(k[2].m, 4.0, kRound);
  EXPECT_NEAR(k[2].x, (2 * 5.0 + 5.2 + 5.4) / 4, kRound);
  EXPECT_NEAR(k[2].v, (2 * 0.30 + 0.30 + 0.31) / 4, kRound);
}

TEST(ClusterFinder, CloseButApproachingBodiesAreSeparate) {
  Bodies b;
  b.push_back(1.0, 1.0, 1);
  b.push_back(1.1, -1.0, 1);
  EXPECT_EQ(find_clusters(b, 0.0, ClusterCriteria{0.5, 0.02}).size(), 2u);
}

TEST(ClusterFinder, RingRunWrapsAcrossZero) {
  const double L = 10.0;
  Bodies b;
  b.push_back(0.1, 0.2, 1);  // wraps with the last two
  b.push_back(4.0, -0.3, 1);
  b.push_back(9.7, 0.2, 1);
  b.push_back(9.9, 0.2, 1);
  const auto k = find_clusters(b, L, ClusterCriteria{0.5, 0.02});
  ASSERT_EQ(k.size(), 2u);
  EXPECT_EQ(k[0].first, 1u);
  EXPECT_EQ(k[0].count, 1u);
  EXPECT_EQ(k[1].first, 2u);
  EXPECT_EQ(k[1].count, 3u);
  // Unrolled centre of mass (9.7 + 9.9 + 10.1) / 3 = 9.9.
  EXPECT_NEAR(k[1].x, 9.9, kRound);
  EXPECT_NEAR(k[1].m, 3.0, kRound);
}

TEST(ClusterFinder, WrappedCentreOfMassIsWrappedIntoRing) {
  const double L = 10.0;
  Bodies b;
  b.push_back(0.3, 0.0, 3);
  b.push_back(9.9, 0.0, 1);
  const auto k = find_clusters(b, L, ClusterCriteria{0.5, 0.02});
  ASSERT_EQ(k.size(), 1u);
  // (9.9 + 3 * 10.3) / 4 = 10.2 -> 0.2.
  EXPECT_NEAR(k[0].x, 0.2, kRound);
}

TEST(ClusterFinder, MergedBodiesAreEachTheirOwnCluster) {
  Rng rng(7);
  Bodies b;
  double x = 0;
  for (int i = 0; i < 50; ++i) {
    x += 1e-9 + rng.uniform();                 // gaps > 0, some tiny
    b.push_back(x, 0.0, 1.0 + rng.uniform());  // equal velocities: only the gap criterion separates
  }
  const auto k = find_clusters(b, x + 1.0, merged_bodies_criteria());
  ASSERT_EQ(k.size(), b.size());
  for (std::size_t i = 0; i < k.size(); ++i) {
    EXPECT_EQ(k[i].first, i);
    EXPECT_EQ(k[i].x, b.x[i]);
    EXPECT_EQ(k[i].m, b.m[i]);
  }
}

TEST(ClusterFinder, PartitionConservesMassAndMomentum) {
  Rng rng(11);
  const double L = 200;
  Bodies b;
  for (int i = 0; i < 200; ++i) b.push_back(i + 0.4 * rng.uniform(), 0.05 * rng.uniform(), 1.0);
  const auto k = find_clusters(b, L, default_cluster_criteria(0.01, 1.0));
  std::size_t members = 0;
  double m = 0, p = 0;
  for (const auto& c : k) {
    members += c.count;
    m += c.m;
    p += c.m * c.v;
    EXPECT_GE(c.x, 0.0);
    EXPECT_LT(c.x, L);
  }
  EXPECT_EQ(members, b.size());
  // 200 terms of size <= 1 (mass) or <= 0.05 (momentum): rounding well below 1e-12.
  EXPECT_NEAR(m, total_mass(b), kRound);
  EXPECT_NEAR(p, total_momentum(b), kRound);
}

TEST(ClusterFinder, FullyLinkedRingIsOneCluster) {
  Bodies b;
  for (int i = 0; i < 4; ++i) b.push_back(0.25 * i, 0.0, 1.0);
  const auto k = find_clusters(b, 1.0, ClusterCriteria{0.5, 0.1});
  ASSERT_EQ(k.size(), 1u);
  EXPECT_EQ(k[0].count, 4u);
}

TEST(ClusterFinder, DefaultCriteriaFollowDeltaSpacingAndTime) {
  const auto c = default_cluster_criteria(0.01, 2.0);
  EXPECT_DOUBLE_EQ(c.max_dv, 0.05);
  EXPECT_DOUBLE_EQ(c.max_gap, 1.0);
  // sqrt(delta t a) = sqrt(0.01 * 1e4 * 1) = 10 once above the floor a / 2.
  EXPECT_DOUBLE_EQ(default_cluster_criteria(0.01, 1.0, 1e4).max_gap, 10.0);
  EXPECT_DOUBLE_EQ(default_cluster_criteria(0.01, 1.0, 1.0).max_gap, 0.5);
  EXPECT_THROW(default_cluster_criteria(0.01, 1.0, -1.0), InputError);
  EXPECT_THROW(default_cluster_criteria(-1.0, 1.0), InputError);
  EXPECT_THROW(default_cluster_criteria(0.01, 0.0), InputError);
}

TEST(ClusterFinder, RejectsBadInput) {
  Bodies b;
  b.push_back(2.0, 0, 1);
  b.push_back(1.0, 0, 1);
  EXPECT_THROW(find_clusters(b, 0.0, ClusterCriteria{}), InputError);
  Bodies outside;
  outside.push_back(11.0, 0, 1);
  EXPECT_THROW(find_clusters(outside, 10.0, ClusterCriteria{}), InputError);
  EXPECT_THROW(find_clusters(Bodies{}, -1.0, ClusterCriteria{}), InputError);
}

// A whole state read in chunks of 7, as a sink reads a model's state; with
// knows_last, telling its last body (StateReader::last: the walk in one read),
// else not (three reads). Counts its reads.
class ChunkedBodies final : public StateReader {
 public:
  ChunkedBodies(const Bodies& b, bool knows_last) : b_(b), knows_last_(knows_last) {}
  std::size_t size() const override { return b_.size(); }
  void read(const Chunk& chunk) const override {
    ++reads;
    for (std::size_t i = 0; i < b_.size(); i += 7)
      chunk(&b_.x[i], &b_.v[i], &b_.m[i], std::min<std::size_t>(7, b_.size() - i));
  }
  std::optional<std::array<double, 3>> last() const override {
    if (!knows_last_ || b_.size() == 0) return std::nullopt;
    return std::array<double, 3>{b_.x.back(), b_.v.back(), b_.m.back()};
  }
  mutable int reads = 0;

 private:
  const Bodies& b_;
  bool knows_last_;
};

std::vector<Cluster> streamed(const Bodies& b, double L, const ClusterCriteria& c, bool knows_last = false,
                              int* reads = nullptr) {
  std::vector<Cluster> out;
  const ChunkedBodies state(b, knows_last);
  visit_clusters(state, L, c, [&](const Cluster& k) { out.push_back(k); });
  if (reads) *reads = state.reads;
  return out;
}

void expect_same_clusters(const std::vector<Cluster>& a, const std::vector<Cluster>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t k = 0; k < a.size(); ++k) {
    EXPECT_EQ(a[k].first, b[k].first);
    EXPECT_EQ(a[k].count, b[k].count);
    EXPECT_EQ(a[k].x, b[k].x);  // bit for bit: the same sums in the same order
    EXPECT_EQ(a[k].v, b[k].v);
    EXPECT_EQ(a[k].m, b[k].m);
  }
}

// Clumps of co-moving bodies, some across the wrap, on a ring of length 100.
Bodies clumpy_state(std::uint64_t seed, bool across_wrap) {
  Rng rng(seed);
  Bodies b;
  double x = across_wrap ? 0.05 : 1.0;
  while (x < 99.5) {
    const double v = rng.uniform(-1.0, 1.0);
    for (int j = 0, n = 1 + static_cast<int>(rng.uniform(0.0, 5.0)); j < n && x < 99.9; ++j, x += 0.1)
      b.push_back(x, v + rng.uniform(-0.005, 0.005), rng.uniform(0.5, 2.0));
    x += rng.uniform(0.6, 3.0);
  }
  if (across_wrap) b.push_back(99.95, b.v.front(), 1.0);  // joins body 0 across x = L
  return b;
}

// Both walks: in one read where the state tells its last body, in three where
// it does not, and where more bodies than the one read holds back lie before
// the ring's start (a ring joined all round: every body before it).
TEST(ClusterFinder, StreamedClustersAreFindClustersToTheBit) {
  const ClusterCriteria c{0.5, 0.02};
  for (bool knows_last : {false, true}) {
    SCOPED_TRACE(knows_last ? "one read" : "three reads");
    for (std::uint64_t seed = 1; seed <= 20; ++seed)
      for (bool wrap : {false, true}) {
        const Bodies b = clumpy_state(seed, wrap);
        int reads = 0;
        expect_same_clusters(streamed(b, 100.0, c, knows_last, &reads), find_clusters(b, 100.0, c));
        EXPECT_EQ(reads, knows_last ? 1 : wrap ? 3 : 2);  // a start past body 0 needs the third
        expect_same_clusters(streamed(b, 0.0, c, knows_last, &reads), find_clusters(b, 0.0, c));
        EXPECT_EQ(reads, 1);  // a line: no wrap to settle
      }
    Bodies linked;  // a fully linked ring is one cluster from body 0
    for (int i = 0; i < 10; ++i) linked.push_back(0.1 * i, 0.0, 1.0);
    expect_same_clusters(streamed(linked, 1.0, c, knows_last), find_clusters(linked, 1.0, c));
    Bodies long_ring;  // 70 000 bodies all joined: more than one read holds back
    for (int i = 0; i < 70000; ++i) long_ring.push_back(0.1 * i, 1e-3 * (i % 3), 1.0);
    int reads = 0;
    expect_same_clusters(streamed(long_ring, 7000.0, c, knows_last, &reads),
                         find_clusters(long_ring, 7000.0, c));
    EXPECT_EQ(reads, knows_last ? 1 + 2 : 2);  // the one read gives up; then a start at body 0: two
    // 70 000 joined bodies from body 0, then clusters of two, the last body joined to body 0 across
    // the wrap: the one read gives up before the start, and visits each cluster once, later.
    Bodies long_head = long_ring;
    for (int k = 0; k < 20; ++k)
      long_head.push_back(7000.0 + 2.0 * k, 5.0, 1.0), long_head.push_back(7000.2 + 2.0 * k, 5.0, 1.0);
    long_head.push_back(7099.95, long_head.v.front(), 1.0);
    expect_same_clusters(streamed(long_head, 7100.0, c, knows_last, &reads),
                         find_clusters(long_head, 7100.0, c));
    EXPECT_EQ(reads, knows_last ? 1 + 3 : 3);
    EXPECT_TRUE(streamed(Bodies{}, 1.0, c, knows_last).empty());
  }
}

// The heaviest cluster of the walk, made without the lighter ones: the first of
// the heaviest of find_clusters (as max_element picks it), to the bit, on both
// walks; ties (clusters of equal mass) go to the first in find_clusters' order.
TEST(ClusterFinder, HeaviestClusterIsTheFirstHeaviestOfFindClustersToTheBit) {
  const ClusterCriteria c{0.5, 0.02};
  auto first_heaviest = [](const std::vector<Cluster>& all) {
    return *std::max_element(all.begin(), all.end(),
                             [](const Cluster& a, const Cluster& b) { return a.m < b.m; });
  };
  auto expect_heaviest = [&](const Bodies& b, double L, bool knows_last) {
    const std::optional<Cluster> h = heaviest_cluster(ChunkedBodies(b, knows_last), L, c);
    ASSERT_TRUE(h);
    expect_same_clusters({*h}, {first_heaviest(find_clusters(b, L, c))});
  };
  Bodies equal;  // clusters of two equal bodies: every cluster is as heavy
  for (int k = 0; k < 30; ++k)
    equal.push_back(3.0 * k + 0.5, 0.1 * k, 1.0), equal.push_back(3.0 * k + 0.6, 0.1 * k, 1.0);
  Bodies long_head;  // the one read gives up before the ring's start
  for (int i = 0; i < 70000; ++i) long_head.push_back(0.1 * i, 1e-3 * (i % 3), 1.0);
  for (int k = 0; k < 20; ++k)
    long_head.push_back(7000.0 + 2.0 * k, 5.0, 1.0), long_head.push_back(7000.2 + 2.0 * k, 5.0, 1.0);
  long_head.push_back(7099.95, long_head.v.front(), 1.0);
  for (bool knows_last : {false, true}) {
    SCOPED_TRACE(knows_last ? "one read" : "three reads");
    for (std::uint64_t seed = 1; seed <= 20; ++seed)
      for (bool wrap : {false, true}) {
        const Bodies b = clumpy_state(seed, wrap);
        expect_heaviest(b, 100.0, knows_last);
        expect_heaviest(b, 0.0, knows_last);
      }
    expect_heaviest(equal, 90.0, knows_last);
    expect_heaviest(equal, 0.0, knows_last);
    expect_heaviest(long_head, 7100.0, knows_last);
    EXPECT_FALSE(heaviest_cluster(ChunkedBodies(Bodies{}, knows_last), 1.0, c));
  }
}

}  // namespace
}  // namespace shockgas::particles
