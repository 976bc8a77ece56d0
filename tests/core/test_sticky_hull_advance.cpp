// Later times from earlier clusters: StickyHull::advance against the hull built
// from the bodies at the same time. Clusters only merge, so both must give the
// same partition, and the same positions and velocities to rounding.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "shockgas/core/error.hpp"
#include "shockgas/core/random.hpp"
#include "shockgas/core/sticky_hull.hpp"

namespace shockgas {
namespace {

struct Case {
  std::size_t n;
  bool ring;
  bool random_positions;
  bool equal_masses;
  std::uint64_t seed;
};

// L = N (unit mean spacing), velocities uniform on [-1, 1].
Bodies gas(const Case& c) {
  Rng rng(c.seed);
  const double L = static_cast<double>(c.n);
  std::vector<double> x(c.n);
  for (std::size_t i = 0; i < c.n; ++i)
    x[i] = c.random_positions ? rng.uniform(0.0, L) : static_cast<double>(i);
  std::sort(x.begin(), x.end());
  Bodies b;
  for (std::size_t i = 0; i < c.n; ++i)
    b.push_back(x[i], rng.uniform(-1.0, 1.0), c.equal_masses ? 1.0 : rng.uniform(0.5, 2.0));
  return b;
}

StickyHull from_scratch(const Bodies& b, const Case& c, double t) {
  return c.ring ? StickyHull::ring(b, static_cast<double>(c.n), t) : StickyHull::line(b, t);
}

std::vector<StickyCluster> chain(const StickyHull& h) {
  std::vector<StickyCluster> out;
  h.for_each([&](const StickyCluster& k) { out.push_back(k); });
  return out;
}

// Sample times as a run uses them: log-spaced, here from 0.01 to 1e4.
std::vector<double> times() {
  std::vector<double> t;
  for (int k = 0; k <= 24; ++k) t.push_back(0.01 * std::pow(10.0, k / 4.0));
  return t;
}

// Same partition exactly. Positions, velocities and masses agree to the
// rounding of merged centres of mass, which runs in another order: measured
// largest |dx| / (L + t) 9e-16 (x grows like v t on the line), |dv| 4e-16
// (means of values in [-1, 1]), |dm| / m 6e-16 (masses 0.5..2, unequal case;
// equal masses are exact counts). 1e-14 is ten times that.
constexpr double kRound = 1e-14;

void expect_advance_equals_scratch(const Case& c) {
  const Bodies b = gas(c);
  const double L = static_cast<double>(c.n);
  const std::vector<double> t = times();
  StickyHull h = from_scratch(b, c, t.front());
  std::size_t merged = 0;
  for (double tk : t) {
    SCOPED_TRACE("t = " + std::to_string(tk));
    h.advance(tk);
    const std::vector<StickyCluster> got = chain(h), want = chain(from_scratch(b, c, tk));
    ASSERT_EQ(got.size(), want.size());
    for (std::size_t k = 0; k < got.size(); ++k) {
      ASSERT_EQ(got[k].first, want[k].first) << "cluster " << k;
      ASSERT_EQ(got[k].count, want[k].count) << "cluster " << k;
      EXPECT_NEAR(got[k].x, want[k].x, kRound * (L + tk)) << "cluster " << k;
      EXPECT_NEAR(got[k].v, want[k].v, kRound) << "cluster " << k;
      EXPECT_NEAR(got[k].m, want[k].m, kRound * want[k].m) << "cluster " << k;
    }
    merged = c.n - got.size();
  }
  EXPECT_GT(merged, c.n / 2);  // the schedule reached late times: most bodies merged
}

TEST(StickyHullAdvance, LineEqualsScratch) {
  for (std::size_t n : {10u, 1000u, 100000u})
    for (std::uint64_t seed : {1u, 2u, 3u}) {
      SCOPED_TRACE("N = " + std::to_string(n) + ", seed " + std::to_string(seed));
      expect_advance_equals_scratch({n, false, seed % 2 == 0, true, seed});
    }
}

TEST(StickyHullAdvance, RingEqualsScratch) {
  for (std::size_t n : {10u, 1000u, 100000u})
    for (std::uint64_t seed : {4u, 5u, 6u}) {
      SCOPED_TRACE("N = " + std::to_string(n) + ", seed " + std::to_string(seed));
      expect_advance_equals_scratch({n, true, seed % 2 == 0, true, seed});
    }
}

TEST(StickyHullAdvance, UnequalMassesEqualScratch) {
  for (bool ring : {false, true})
    for (std::uint64_t seed : {7u, 8u}) {
      SCOPED_TRACE(std::string(ring ? "ring" : "line") + ", seed " + std::to_string(seed));
      expect_advance_equals_scratch({20000, ring, seed % 2 == 0, false, seed});
    }
}

TEST(StickyHullAdvance, SameTimeKeepsTheStateEarlierTimeIsRefused) {
  const Bodies b = gas({1000, true, false, true, 9});
  StickyHull h = StickyHull::ring(b, 1000.0, 50.0);
  const std::vector<StickyCluster> before = chain(h);
  h.advance(50.0);
  const std::vector<StickyCluster> after = chain(h);
  ASSERT_EQ(after.size(), before.size());
  for (std::size_t k = 0; k < after.size(); ++k) EXPECT_EQ(after[k].count, before[k].count);
  EXPECT_THROW(h.advance(10.0), InputError);
}

}  // namespace
}  // namespace shockgas
