// A solver's fields at several output times (series.hpp): the exact solver
// evaluated at each time, a marching solver continued from its own cell
// averages, and the restart state that carries it.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "shockgas/continuum/registry.hpp"
#include "shockgas/continuum/series.hpp"
#include "shockgas/continuum/solve.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::continuum {
namespace {

InitialField sine() {
  InitialField f;
  f.length = 1.0;
  f.v0 = [](double x) { return 0.5 + std::sin(2 * std::numbers::pi * x); };
  f.rho0 = [](double) { return 1.0; };
  return f;
}

ContinuumParams params(std::size_t cells) {
  ContinuumParams p;
  p.cells = cells;
  return p;
}

double l1(const std::vector<double>& a, const std::vector<double>& b, double dx) {
  double s = 0;
  for (std::size_t i = 0; i < a.size(); ++i) s += std::abs(a[i] - b[i]);
  return s * dx;
}

TEST(Series, TimeZeroIsTheCellAveragesOfTheInitialData) {
  const auto p = params(64);
  const auto series = solve_at_times("godunov", sine(), p, {0.0});
  const CellAverages a = cell_averages(sine(), 64);
  ASSERT_EQ(series.size(), 1u);
  EXPECT_EQ(series[0].t, 0.0);
  EXPECT_EQ(series[0].v, a.v);
  EXPECT_EQ(series[0].rho, a.rho);
  EXPECT_EQ(series[0].solver, "godunov");
}

TEST(Series, DirectSolverIsEvaluatedAtEachTimeFromTheStart) {
  const auto p = params(128);
  const std::vector<double> times = {0.05, 0.2, 0.45};
  const auto series = solve_at_times("hopf_lax", sine(), p, times);
  ASSERT_EQ(series.size(), times.size());
  for (std::size_t k = 0; k < times.size(); ++k) {
    const ContinuumResult direct = solve("hopf_lax", sine(), p, times[k]);
    EXPECT_EQ(series[k].t, times[k]);
    EXPECT_EQ(series[k].v, direct.v) << "t = " << times[k];  // the same evaluation, bit for bit
    EXPECT_EQ(series[k].rho, direct.rho);
  }
}

TEST(Series, PiecewiseConstantFieldHasTheStateAsItsCellAverages) {
  ContinuumResult r = solve("godunov", sine(), params(100), 0.3);
  const CellAverages a = cell_averages(piecewise_constant_field(r), 100);
  for (std::size_t i = 0; i < 100; ++i) {
    // 6 Gauss nodes inside each cell, all on one constant piece: the weights
    // sum to 2 in rounding only
    EXPECT_NEAR(a.v[i], r.v[i], 4e-16 * (1 + std::abs(r.v[i])));
    EXPECT_NEAR(a.rho[i], r.rho[i], 4e-16 * (1 + std::abs(r.rho[i])));
  }
}

TEST(Series, MarchingSolverContinuesFromItsOwnState) {
  // Restarting at each output time changes only where steps end: the result at
  // the last time is as close to the exact solution as the solve that went
  // there in one go (first order: L1 ~ dx; measured 4.2e-3 both), and the two
  // differ far less than either's error (measured 4.6e-5: a twentieth allows
  // for the step sequence, not for a wrong restart state).
  const auto p = params(256);
  const double dx = 1.0 / 256;
  std::vector<double> times;
  for (int k = 0; k <= 10; ++k) times.push_back(0.05 * k);
  const auto series = solve_at_times("godunov", sine(), p, times);
  ASSERT_EQ(series.size(), times.size());
  const ContinuumResult straight = solve("godunov", sine(), p, 0.5);
  const ContinuumResult exact = solve("hopf_lax", sine(), p, 0.5);
  const double err_straight = l1(straight.v, exact.v, dx), err_series = l1(series.back().v, exact.v, dx);
  EXPECT_EQ(series.back().t, 0.5);
  EXPECT_LT(err_series, 1.1 * err_straight);
  EXPECT_LT(l1(series.back().v, straight.v, dx), 0.05 * err_straight);
  // mass kept across the restarts (conservative scheme: rounding)
  double m = 0;
  for (double rho : series.back().rho) m += rho * dx;
  EXPECT_NEAR(m, 1.0, 1e-13);
}

TEST(Series, RepeatedTimeRepeatsTheFields) {
  const auto series = solve_at_times("godunov", sine(), params(64), {0.1, 0.1});
  ASSERT_EQ(series.size(), 2u);
  EXPECT_EQ(series[0].v, series[1].v);
}

TEST(Series, RejectsTimesOutOfOrderOrNegative) {
  EXPECT_THROW(solve_at_times("godunov", sine(), params(64), {0.2, 0.1}), InputError);
  EXPECT_THROW(solve_at_times("godunov", sine(), params(64), {-0.1}), InputError);
  EXPECT_THROW(solve_at_times("no_such_solver", sine(), params(64), {0.1}), InputError);
}

// Outflow boundaries are solved by the finite-volume schemes only; every other
// solver solves the periodic problem, so it refuses outflow (finding: hopf_lax,
// hopf_cole, cvode and arkode returned the periodic solution as the outflow one,
// a fan coming in through the wrapped edge).
TEST(Series, ASolverThatSolvesThePeriodicProblemOnlyRefusesOutflow) {
  auto p = params(64);
  p.boundary = Boundary::outflow;
  for (const SolverInfo& s : registered_solvers()) {
    if (s.outflow) {
      EXPECT_NO_THROW(solve(s.name, sine(), p, 0.05)) << s.name;
      continue;
    }
    EXPECT_THROW(solve(s.name, sine(), p, 0.05), InputError) << s.name;
    EXPECT_THROW(solve_at_times(s.name, sine(), p, {0.05}), InputError) << s.name;
    EXPECT_THROW(preflight(s.name, sine(), p, 0.05), InputError) << s.name;
  }
}

}  // namespace
}  // namespace shockgas::continuum
