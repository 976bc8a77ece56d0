// A finite-volume grid cut into segments, each stepped by a thread of its own
// (godunov_scheme.hpp): the same cells to the bit as in one piece, whatever the
// scheme, the boundary or the number of segments.
#include <gtest/gtest.h>

#include <cmath>
#include <type_traits>
#include <vector>

#include "shockgas/continuum/burgers_physics.hpp"
#include "shockgas/continuum/godunov_scheme.hpp"
#include "shockgas/continuum/limiters.hpp"
#include "shockgas/continuum/pressureless_physics.hpp"
#include "shockgas/continuum/solve.hpp"
#include "shockgas/core/random.hpp"

namespace shockgas::continuum {
namespace {

// Random velocities v and densities rho: (v, rho) for Burgers + continuity,
// (rho, rho v) for the pressureless gas.
template <class Physics>
std::vector<typename Physics::State> random_cells(std::size_t n, std::uint64_t seed) {
  Rng rng(seed);
  std::vector<typename Physics::State> cells(n);
  for (auto& c : cells) {
    const double v = rng.uniform(-1.0, 1.0), rho = rng.uniform(0.5, 1.5);
    if constexpr (std::is_same_v<Physics, PressurelessGas>)
      c = {rho, rho * v};
    else
      c = {v, rho};
  }
  return cells;
}

template <class Physics, class Step>
void expect_same_cells_in_segments(Boundary boundary, const Step& step) {
  const std::size_t n = 3 * kSegmentCells + 17;
  const auto cells = random_cells<Physics>(n, 7);
  FiniteVolumeGrid<Physics> whole(cells, 1.0, boundary), cut(cells, 1.0, boundary, 3);
  const TimeLoop loop{40.0, 0.5, "segments", {}};
  const std::size_t steps = advance(whole, loop, [&](double dt) { return step(whole, dt); });
  EXPECT_EQ(advance(cut, loop, [&](double dt) { return step(cut, dt); }), steps);
  EXPECT_GT(steps, 20u);
  std::size_t differ = 0;
  for (std::size_t i = 0; i < n; ++i) differ += whole.cell(i) != cut.cell(i);
  EXPECT_EQ(differ, 0u);
  // Not a grid that stood still: the cells moved from where they started.
  EXPECT_NE(whole.cell(kSegmentCells), cells[kSegmentCells]);
}

TEST(GodunovSegments, StepTheCellsOfOnePieceToTheBit) {
  for (Boundary b : {Boundary::periodic, Boundary::outflow}) {
    SCOPED_TRACE(b == Boundary::periodic ? "periodic" : "outflow");
    expect_same_cells_in_segments<BurgersContinuity>(b,
                                                     [](auto& g, double dt) { return g.step_godunov(dt); });
    expect_same_cells_in_segments<BurgersContinuity>(
        b, [](auto& g, double dt) { return g.template step_muscl_hancock<McLimiter>(dt); });
    expect_same_cells_in_segments<PressurelessGas>(b, [](auto& g, double dt) { return g.step_godunov(dt); });
  }
}

// continuum.threads through the registered solvers: one thread or three, the same fields.
TEST(GodunovSegments, TheSolversGiveTheSameFieldsOnAnyNumberOfThreads) {
  InitialField f;
  f.length = 1.0;
  f.v0 = [](double x) { return std::sin(2 * M_PI * x) + 0.3 * std::sin(14 * M_PI * x); };
  f.rho0 = [](double x) { return 1.0 + 0.5 * std::cos(6 * M_PI * x); };
  for (const char* name : {"godunov", "godunov2", "pressureless"}) {
    SCOPED_TRACE(name);
    ContinuumParams p;
    p.cells = 3 * kSegmentCells + 17;
    p.threads = 1;
    const ContinuumResult one = solve(name, f, p, 0.05);
    p.threads = 3;
    const ContinuumResult three = solve(name, f, p, 0.05);
    EXPECT_EQ(one.v, three.v);
    EXPECT_EQ(one.rho, three.rho);
    EXPECT_EQ(one.stats.at("steps"), three.stats.at("steps"));
  }
}

TEST(GodunovSegments, ASmallGridIsOnePiece) {
  EXPECT_EQ(grid_threads(kSegmentCells - 1, 8), 1u);
  EXPECT_EQ(grid_threads(2 * kSegmentCells, 8), 2u);
  EXPECT_EQ(grid_threads(100 * kSegmentCells, 3), 3u);
  EXPECT_EQ(grid_threads(100 * kSegmentCells, 0), 1u);
}

}  // namespace
}  // namespace shockgas::continuum
