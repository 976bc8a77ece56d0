// Why a fitted cooling exponent departs from -2/3 (cooling_corrections.hpp):
// the measured corrections, and the words report.md gives a departure.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "shockgas/compare/cooling_corrections.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::compare {
namespace {

bool says(const std::string& text, const std::string& words) { return text.find(words) != std::string::npos; }

JackknifeEstimate estimate(double value, double error) { return {value, error, 0.0, 2, 0}; }

TEST(CoolingCorrections, ShiftTheExponentByTheLatticeExcessAndTheFiniteSizeDeficit) {
  // The shift of a relative excess d(t): (ln(1 + d(t_max)) - ln(1 + d(t_min))) / ln(t_max / t_min),
  // with d = 0.06 t^(-2/3) (lattice) and -2.75 / (1.9 N t^(-2/3)) (finite size).
  const double N = 20000, lo = 100, hi = 1e4, span = std::log(hi / lo);
  const auto clusters = [&](double t) { return 1.9 * N * std::pow(t, -2.0 / 3.0); };
  const double lattice =
      (std::log1p(0.06 * std::pow(hi, -2.0 / 3.0)) - std::log1p(0.06 * std::pow(lo, -2.0 / 3.0))) / span;
  const double finite = (std::log1p(-2.75 / clusters(hi)) - std::log1p(-2.75 / clusters(lo))) / span;
  const CoolingCorrections c = cooling_corrections(20000, true, lo, hi);
  EXPECT_NEAR(c.lattice, lattice, 1e-15);
  EXPECT_NEAR(c.finite_size, finite, 1e-15);
  EXPECT_NEAR(c.clusters_end, clusters(hi), 1e-9);
  EXPECT_NEAR(c.expected, -2.0 / 3.0 + lattice + finite, 1e-15);
  EXPECT_NEAR(c.finite_size, -0.0071, 5e-5);  // what the default scene's report prints
  EXPECT_EQ(cooling_corrections(20000, false, lo, hi).lattice, 0.0);  // random positions: no lattice excess
  EXPECT_THROW(cooling_corrections(20000, true, hi, lo), InputError);
}

TEST(CoolingCorrections, StudentsQuantilesFromTheTableAndBeyond) {
  EXPECT_EQ(student_t_95(1), 12.706);
  EXPECT_EQ(student_t_95(30), 2.042);
  EXPECT_NEAR(student_t_95(60), 2.000, 1e-3);   // A & S 26.7: 2.000
  EXPECT_NEAR(student_t_95(120), 1.980, 1e-3);  // 1.980
  EXPECT_THROW(student_t_95(0), InputError);
}

// The default scene's numbers: a = -0.6972 +- 0.0011 from 2 realizations on [10^2, 10^4].
TEST(CoolingCorrections, ADepartureIsGivenItsMeasuredCause) {
  const CoolingCorrections c = cooling_corrections(20000, true, 100, 1e4);
  const double a = -0.6972, sigma = 0.0011;
  EXPECT_TRUE(says(cooling_departure_text(-0.667, sigma, 2, c, 100, 1e4), "within the statistical error"));
  EXPECT_TRUE(says(cooling_departure_text(c.expected + sigma, sigma, 2, c, 100, 1e4),
                   "the corrections account for it"));
  EXPECT_TRUE(says(cooling_departure_text(a, std::nan(""), 1, c, 100, 1e4), "cannot be weighed"));
  // Without the sticky gas of the same starts: only Student's t of 1 degree of freedom can judge.
  EXPECT_TRUE(
      says(cooling_departure_text(a, 0.002, 2, c, 100, 1e4), "is within the statistics of 2 realizations"));
  EXPECT_TRUE(
      says(cooling_departure_text(a, sigma, 2, c, 100, 1e4), "beyond the statistics of 2 realizations"));
  // With it: the gas as far from -2/3 as the sticky gas of its starts is the starts' spread ...
  const PairedExponents same{estimate(-0.6974, 0.0035), estimate(0.0002, 0.0024)};
  const std::string starts = cooling_departure_text(a, sigma, 2, c, 100, 1e4, same);
  EXPECT_TRUE(says(starts, "gives a = -0.6974 +- 0.0035")) << starts;
  EXPECT_TRUE(says(starts, "is these starts' own")) << starts;
  // ... and a gas that departs from it by more than 2 paired errors departs by its dynamics.
  const PairedExponents apart{estimate(-0.675, 0.0035), estimate(-0.022, 0.0024)};
  const std::string own = cooling_departure_text(a, sigma, 2, c, 100, 1e4, apart);
  EXPECT_TRUE(says(own, "is the gas's own")) << own;
  EXPECT_FALSE(says(own, "these starts' own")) << own;
  // A sticky gas at the corrected value, the gas within 2 paired errors of it: the pairs' errors hold it all.
  const PairedExponents wide{estimate(c.expected, 0.004), estimate(-0.015, 0.01)};
  const std::string pairs = cooling_departure_text(a, sigma, 2, c, 100, 1e4, wide);
  EXPECT_TRUE(says(pairs, "within the errors of the pairs")) << pairs;
  EXPECT_FALSE(says(pairs, "these starts' own")) << pairs;
  // Pairs without an error (a leave-one-out fit failed) weigh nothing: Student's t of 1 degree of freedom
  // does.
  const PairedExponents blind{estimate(-0.6974, 0.0035), estimate(0.0002, std::nan(""))};
  const std::string none = cooling_departure_text(a, sigma, 2, c, 100, 1e4, blind);
  EXPECT_TRUE(says(none, "0.0002 (no jackknife error)")) << none;
  EXPECT_TRUE(says(none, "beyond the statistics of 2 realizations")) << none;
  EXPECT_FALSE(says(none, "nan")) << none;
}

}  // namespace
}  // namespace shockgas::compare
