// The contact times the engine computes while it loads its bodies
// (EventEngine::load_bodies, two pairs at a time without branches, chunk by
// chunk): at t = 0 every body sits at its x, so pair (i, i + 1) meets at
// gap / g when it approaches (g = v_i - v_{i+1} > 0) and never otherwise; the
// ring's last pair counts its right body at x + L.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "engine_fixtures.hpp"

namespace shockgas::particles::detail {
namespace {

// n sorted positions in [0, n) and velocities in [-1, 1], with the cases the
// branch-free loop must get right: equal neighbours' positions (a zero gap),
// equal velocities (g = 0), and receding pairs.
Bodies chain(std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> pos(0.0, static_cast<double>(n)), vel(-1.0, 1.0);
  Bodies c;
  c.x.resize(n), c.v.resize(n), c.m.assign(n, 1.0);
  for (double& x : c.x) x = pos(rng);
  std::sort(c.x.begin(), c.x.end());
  for (double& v : c.v) v = vel(rng);
  for (std::size_t i = 7; i + 1 < n; i += 97) c.x[i + 1] = c.x[i];
  for (std::size_t i = 11; i + 1 < n; i += 89) c.v[i + 1] = c.v[i];
  return c;
}

double expected_time(double gap, double g) {
  return g > 0 ? std::max(gap, 0.0) / g : std::numeric_limits<double>::infinity();
}

// Odd and even sizes, below, at and across the loader's chunks of 4096 bodies.
TEST(EngineLoad, SlotTimesAreTheInitialContactTimes) {
  for (std::size_t n : {2, 3, 4095, 4096, 4097, 12290, 12291}) {
    const Bodies c = chain(n, 1000 + n);
    for (bool ring : {false, true}) {
      const EventEngine<false> e = engine_of<false>(c, ring, CollisionRule{0.9, 1e-2, false});
      for (std::size_t i = 0; i + 1 < n; ++i)
        ASSERT_EQ(e.slot_time(i), expected_time(c.x[i + 1] - c.x[i], c.v[i] - c.v[i + 1]))
            << "n = " << n << ", ring " << ring << ", slot " << i;
      const double last =
          ring ? expected_time((c.x[0] + static_cast<double>(n)) - c.x[n - 1], c.v[n - 1] - c.v[0])
               : std::numeric_limits<double>::infinity();
      EXPECT_EQ(e.slot_time(n - 1), last) << "n = " << n << ", ring " << ring;
    }
  }
}

// The fixtures reach every case the oracle separates.
TEST(EngineLoad, TheChainHoldsZeroGapsEqualVelocitiesAndRecedingPairs) {
  const Bodies c = chain(4097, 1);
  std::size_t zero_gap = 0, equal = 0, receding = 0, approaching = 0;
  for (std::size_t i = 0; i + 1 < c.x.size(); ++i) {
    zero_gap += c.x[i + 1] == c.x[i];
    const double g = c.v[i] - c.v[i + 1];
    equal += g == 0;
    receding += g < 0;
    approaching += g > 0;
  }
  EXPECT_GT(zero_gap, 10u);
  EXPECT_GT(equal, 10u);
  EXPECT_GT(receding, 1000u);
  EXPECT_GT(approaching, 1000u);
}

}  // namespace
}  // namespace shockgas::particles::detail
