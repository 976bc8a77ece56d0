// The streamed initial condition: the same bodies in any chunks.
#include <gtest/gtest.h>

#include <algorithm>

#include "shockgas/core/initial_stream.hpp"

namespace shockgas {
namespace {

Bodies read_in_chunks(const InitialParams& p, std::size_t chunk) {
  InitialStream s(p, 5);
  Bodies b;
  b.x.resize(p.N), b.v.resize(p.N), b.m.resize(p.N);
  for (std::size_t i = 0; s.remaining() > 0; i += chunk) {
    const std::size_t count = std::min(chunk, s.remaining());
    s.next(count, b.x.data() + i, b.v.data() + i, b.m.data() + i);
  }
  return b;
}

TEST(InitialStream, ChunksDoNotChangeTheBodies) {
  for (Positions positions : {Positions::lattice, Positions::random}) {
    for (Velocities velocities : {Velocities::uniform, Velocities::gaussian}) {
      SCOPED_TRACE(std::string(name_of(positions)) + " " + std::string(name_of(velocities)));
      InitialParams p;
      p.N = 10007;
      p.positions = positions;
      p.velocities = velocities;
      p.remove_mean = true;
      const Bodies whole = make_initial_bodies(p, 5);
      const Bodies chunked = read_in_chunks(p, 1000);
      EXPECT_EQ(chunked.x, whole.x);
      EXPECT_EQ(chunked.v, whole.v);
      EXPECT_EQ(chunked.m, whole.m);
      EXPECT_TRUE(std::is_sorted(chunked.x.begin(), chunked.x.end()));
      EXPECT_NEAR(total_momentum(chunked), 0.0, 1e-11);  // rounding of 10^4 terms of O(1)
    }
  }
}

TEST(InitialStream, OnlyGeneratedConditionsStream) {
  InitialParams p;
  EXPECT_TRUE(InitialStream::streamable(p));
  p.velocities = Velocities::expression;
  EXPECT_FALSE(InitialStream::streamable(p));
  p.velocities = Velocities::file;
  EXPECT_FALSE(InitialStream::streamable(p));
}

}  // namespace
}  // namespace shockgas
