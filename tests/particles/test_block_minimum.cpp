// The block minimum of the event tree's leaves against a plain scan: the
// smallest time and the first lane that holds it, with ties and +inf common.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

#include "shockgas/core/random.hpp"
#include "shockgas/particles/block_minimum.hpp"

namespace shockgas::particles::detail {
namespace {

constexpr double never = std::numeric_limits<double>::infinity();
using Block = std::array<double, block_lanes>;

// Times from a few values and +inf, so that most blocks hold ties.
double few_values(Rng& rng) { return rng.uniform() < 0.15 ? never : std::floor(rng.uniform(0.0, 6.0)); }

LaneWinner scan(const Block& t) {
  std::uint32_t first = 0;
  for (std::uint32_t l = 1; l < block_lanes; ++l)
    if (t[l] < t[first]) first = l;
  return {key_of(t[first]), first};
}

TEST(BlockMinimum, LaneWinnerIsTheFirstLaneOfTheMinimum) {
  Rng rng(11);
  for (int trial = 0; trial < 20000; ++trial) {
    alignas(128) Block t;
    for (double& x : t) x = few_values(rng);
    if (trial == 0) t.fill(never);  // all +inf: lane 0
    const LaneWinner fast = lane_winner(t.data()), plain = scan(t);
    ASSERT_EQ(fast.t, plain.t) << trial;
    ASSERT_EQ(fast.lane, plain.lane) << trial;
  }
}

// take_earlier_lane is the lexicographic minimum of (time, lane).
TEST(BlockMinimum, TakeEarlierLaneIsLexicographic) {
  Rng rng(12);
  for (int trial = 0; trial < 20000; ++trial) {
    const double a = few_values(rng), b = few_values(rng);
    const auto la = static_cast<std::uint32_t>(rng.uniform() * 4),
               lb = static_cast<std::uint32_t>(rng.uniform() * 4);
    TimeKey t = key_of(a);
    std::uint32_t lane = la;
    take_earlier_lane(t, lane, key_of(b), lb);
    const bool take = b < a || (b == a && lb < la);
    ASSERT_EQ(t, key_of(take ? b : a)) << a << " " << la << " " << b << " " << lb;
    ASSERT_EQ(lane, take ? lb : la) << a << " " << la << " " << b << " " << lb;
  }
}

#if defined(__AVX512F__)
// A bounce's winner from the block's other lanes (taken before the new times are
// known) and two compares equals the minimum of the merged block, for every
// offset whose three lanes lie in one block.
TEST(BlockMinimum, EarliestWithTheThreeIsTheMergedMinimum) {
  Rng rng(13);
  for (int trial = 0; trial < 20000; ++trial) {
    alignas(128) Block t;
    for (double& x : t) x = few_values(rng);
    const auto o = static_cast<std::uint32_t>(trial % (block_lanes - 2));
    double tp = few_values(rng), tj = few_values(rng);
    if (trial < static_cast<int>(block_lanes)) t.fill(never), tp = tj = never;  // all +inf: lane 0
    const ThreeTimes three(o, tp, never, tj);
    ASSERT_TRUE(three.one_block());
    const __m512d low = _mm512_load_pd(t.data()), high = _mm512_load_pd(t.data() + 8);
    const LaneWinner rest = lane_winner(three.cleared(low, 0), three.cleared(high, 1));
    const LaneWinner fast = three.earliest_with(rest, key_of(tp), key_of(tj));
    t[o] = tp, t[o + 1] = never, t[o + 2] = tj;
    const LaneWinner plain = scan(t);
    ASSERT_EQ(fast.t, plain.t) << trial;
    ASSERT_EQ(fast.lane, plain.lane) << trial;
  }
}
#endif

}  // namespace
}  // namespace shockgas::particles::detail
