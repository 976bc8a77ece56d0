// An initial condition that keeps nothing of realization 0 (Keep::stream):
// every reader draws the same bodies in chunks, and what is computed from them
// is the same to the bit as from a whole copy.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstdint>

#include "shockgas/core/error.hpp"
#include "shockgas/core/initial_stream.hpp"
#include "shockgas/core/sticky_hull.hpp"

namespace shockgas {
namespace {

using Keep = InitialCondition::Keep;

InitialParams gas(Positions positions, Velocities velocities) {
  InitialParams p;
  p.N = 10007;
  p.positions = positions;
  p.velocities = velocities;
  p.remove_mean = true;
  p.seed = 42;
  return p;
}

Bodies drawn(const InitialCondition& initial, std::uint64_t k) {
  InitialStream s = stream_realization(initial, k);
  Bodies b;
  read_in_chunks(
      s,
      [&](const double* x, const double* v, const double* m, std::size_t count) {
        for (std::size_t i = 0; i < count; ++i) b.push_back(x[i], v[i], m[i]);
      },
      999);
  return b;
}

bool same_bits(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

TEST(StreamedInitial, HoldsNoBodiesAndDrawsTheSameOnes) {
  for (Positions positions : {Positions::lattice, Positions::random})
    for (Velocities velocities : {Velocities::uniform, Velocities::gaussian}) {
      const InitialParams p = gas(positions, velocities);
      const InitialCondition streamed(p, Keep::stream);
      EXPECT_FALSE(streamed.holds_bodies());
      EXPECT_THROW((void)streamed.bodies(), RunError);
      EXPECT_EQ(streamed.field().bodies.size(), 0u);
      EXPECT_EQ(streamed.length(), InitialCondition(p).length());
      for (std::uint64_t k : {0u, 3u}) {
        const Bodies whole = make_initial_bodies(p, k);
        const Bodies b = drawn(streamed, k);
        EXPECT_EQ(b.x, whole.x);
        EXPECT_EQ(b.v, whole.v);
        EXPECT_EQ(b.m, whole.m);
        // As a run finds it: one pass as the bodies are drawn (TemperatureSums), to the bit;
        // temperature()'s two passes to rounding (both about N eps = 1.1e-12 relative).
        TemperatureSums sums;
        sums.add(whole.v.data(), whole.m.data(), whole.size());
        EXPECT_TRUE(same_bits(initial_temperature(streamed, k), sums.temperature()));
        EXPECT_NEAR(initial_temperature(streamed, k), temperature(whole), 2.2e-12 * temperature(whole));
      }
    }
}

// A stream of the velocities alone skips the positions' draws (random
// positions are then neither kept nor sorted) and gives the same velocities.
TEST(StreamedInitial, VelocitiesAloneAreTheVelocitiesOfTheWholeStream) {
  for (Positions positions : {Positions::lattice, Positions::random})
    for (bool remove_mean : {false, true}) {
      InitialParams p = gas(positions, Velocities::gaussian);
      p.remove_mean = remove_mean;
      for (std::uint64_t k : {0u, 5u}) {
        const Bodies whole = make_initial_bodies(p, k);
        InitialStream s(p, k, InitialStream::Parts::velocities);
        std::vector<double> v, m;
        read_in_chunks(
            s,
            [&](const double*, const double* vc, const double* mc, std::size_t count) {
              v.insert(v.end(), vc, vc + count), m.insert(m.end(), mc, mc + count);
            },
            1000);
        EXPECT_EQ(v, whole.v) << "positions " << static_cast<int>(positions) << ", k = " << k;
        EXPECT_EQ(m, whole.m);
      }
    }
}

// Summed in blocks about their own means, whatever the chunks: the same bits
// for any chunking, and no cancellation where the first body is far from the
// mean (a shift by the first velocity lost 1e-3 of T here): within 2 N eps of
// temperature()'s two passes.
TEST(TemperatureSums, AreTheTwoPassTemperatureWhateverTheChunksAndTheFirstBody) {
  Bodies b;
  b.push_back(0.0, 1e5, 1e-6);  // far out, light
  std::uint64_t state = 12345;
  for (int k = 1; k < 100000; ++k) {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    b.push_back(k, static_cast<double>(state >> 11) * 0x1p-53 - 0.5, 1.0);
  }
  const double exact = temperature(b);
  // 5000: a block part-filled, then whole blocks in place after it
  for (std::size_t chunk :
       {std::size_t{1}, std::size_t{999}, std::size_t{4096}, std::size_t{5000}, b.size()}) {
    TemperatureSums sums;
    for (std::size_t i = 0; i < b.size(); i += chunk)
      sums.add(b.v.data() + i, b.m.data() + i, std::min(chunk, b.size() - i));
    TemperatureSums whole;
    whole.add(b.v.data(), b.m.data(), b.size());
    EXPECT_TRUE(same_bits(sums.temperature(), whole.temperature())) << "chunks of " << chunk;
    EXPECT_NEAR(sums.temperature(), exact, 2 * 1e5 * 0x1p-52 * exact) << "chunks of " << chunk;
    // The energy: one sum in the bodies' order, as kinetic_energy's, whatever the chunks.
    EXPECT_TRUE(same_bits(sums.kinetic_energy(), kinetic_energy(b))) << "chunks of " << chunk;
  }
}

TEST(StreamedInitial, DataThatCannotBeDrawnAreHeld) {
  InitialParams p;
  p.velocities = Velocities::expression;
  const InitialCondition c(p, Keep::stream);
  EXPECT_TRUE(c.holds_bodies());
  EXPECT_EQ(c.bodies().size(), p.N);
  TemperatureSums sums;
  sums.add(c.bodies().v.data(), c.bodies().m.data(), c.bodies().size());
  EXPECT_TRUE(same_bits(initial_temperature(c, 0), sums.temperature()));
}

// The hull from bodies read in chunks is the hull from the whole copy, to the bit.
TEST(StreamedInitial, HullFromChunksEqualsHullFromBodies) {
  const InitialParams p = gas(Positions::random, Velocities::uniform);
  const Bodies whole = make_initial_bodies(p, 1);
  const double L = domain_length(p);
  for (bool ring : {false, true})
    for (double t : {0.0, 3.0, 300.0}) {
      InitialStream s(p, 1);
      const StickyHull::Chunks read = [&](std::size_t n, double* x, double* v, double* m) {
        s.next(n, x, v, m);
      };
      const StickyHull chunked = ring ? StickyHull::ring(p.N, read, L, t) : StickyHull::line(p.N, read, t);
      const StickyHull from_bodies = ring ? StickyHull::ring(whole, L, t) : StickyHull::line(whole, t);
      const auto a = chunked.clusters(), b = from_bodies.clusters();
      ASSERT_EQ(a.size(), b.size());
      for (std::size_t k = 0; k < a.size(); ++k) {
        EXPECT_TRUE(same_bits(a[k].x, b[k].x) && same_bits(a[k].v, b[k].v) && same_bits(a[k].m, b[k].m));
        EXPECT_EQ(a[k].first, b[k].first);
        EXPECT_EQ(a[k].count, b[k].count);
      }
    }
}

TEST(StreamedInitial, HullFromChunksRefusesUnequalMassesAndDisorder) {
  const StickyHull::Chunks unequal = [](std::size_t n, double* x, double* v, double* m) {
    for (std::size_t i = 0; i < n; ++i) x[i] = static_cast<double>(i), v[i] = 0, m[i] = 1.0 + (i % 2);
  };
  EXPECT_THROW(StickyHull::line(10, unequal, 1.0), InputError);
  const StickyHull::Chunks unsorted = [](std::size_t n, double* x, double* v, double* m) {
    for (std::size_t i = 0; i < n; ++i) x[i] = -static_cast<double>(i), v[i] = 0, m[i] = 1.0;
  };
  EXPECT_THROW(StickyHull::line(10, unsorted, 1.0), InputError);
}

}  // namespace
}  // namespace shockgas
