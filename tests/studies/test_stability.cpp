// The stability detections of `shockgas bench` (docs/performance.md): each scan
// must find the failure where the analysis puts it, and report it, not a NaN.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "process_temp_path.hpp"
#include "shockgas/continuum/explicit_viscous.hpp"
#include "shockgas/core/error.hpp"
#include "shockgas/studies/common.hpp"
#include "shockgas/studies/stability.hpp"

namespace shockgas::studies {
namespace {

TEST(BenchStability, CflScanFindsTheFirstOrderLimitAtOne) {
  // Godunov is monotone for Courant numbers <= 1 (godunov_scheme.hpp); the scan's
  // resolution here is 0.1, so the limit must fall between 1.0 and 1.1 (or 1.2,
  // if growth just past 1 stays under the 1 % detection threshold in this time).
  const auto points = cfl_scan(problem_by_name("sine_post"), "godunov", "mc", 128, {0.8, 0.9, 1.0, 1.1, 1.2});
  const ScanLimit lim = cfl_limit(points);
  EXPECT_EQ(lim.last_stable, 1.0);
  EXPECT_GT(lim.first_failed, 1.0);
  EXPECT_LE(lim.first_failed, 1.2);
  for (const auto& pt : points) EXPECT_FALSE(pt.what.empty());
}

TEST(BenchStability, ExplicitViscousFailsPastTheDiffusiveLimit) {
  // nu = 0.1 on 64 cells: |v| h / 2 nu = 1.5 / 12.8, predicted limit 1/(1 + 0.117) = 0.895 h^2/2nu.
  const Problem pb = problem_by_name("sine_pre");
  const ViscousPoint below = explicit_viscous_point(pb, 0.1, 64, 0.8, 2000);
  const ViscousPoint above = explicit_viscous_point(pb, 0.1, 64, 1.2, 2000);
  // max|v0| is the largest cell average, 1.5 to O((pi/64)^2 / 6) = 4e-4 relative
  EXPECT_NEAR(below.c_predicted, 1 / (1 + 1.5 / 64 / 0.2), 1e-3);
  EXPECT_FALSE(below.failed);
  EXPECT_EQ(below.steps, 2000u);
  EXPECT_TRUE(above.failed);
  EXPECT_LT(above.steps, 2000u);  // stopped at the blow-up, not run on
  EXPECT_TRUE(std::isfinite(above.tv_ratio));
}

TEST(BenchStability, HopfColeFftDetectedFailingBeyondItsLimit) {
  const Problem pb = problem_by_name("sine_post");
  const HopfColePoint ok = hopf_cole_point(pb, 256, 5.0);
  EXPECT_TRUE(ok.fft_finite);
  EXPECT_LT(ok.fft_error, 1e-9);  // eps e^5 log2(256) ~ 3e-13, with margin
  EXPECT_EQ(ok.solver_fft.rfind("accepted", 0), 0u) << ok.solver_fft;
  // At DeltaPsi/2nu = 200 the FFT's relative error eps e^200 has no digits left.
  const HopfColePoint bad = hopf_cole_point(pb, 256, 200.0);
  EXPECT_TRUE(!bad.fft_finite || bad.fft_error > 1e-3) << bad.fft_error;
  EXPECT_EQ(bad.solver_fft.rfind("refused", 0), 0u) << bad.solver_fft;
  EXPECT_EQ(bad.solver_auto.find("failed"), std::string::npos) << bad.solver_auto;  // the log path takes over
  EXPECT_GT(hopf_cole_predicted_break(1024, 1e-3), 20.0);  // ln(1e-3 / (2.2e-16 * 10)) = 26.8
  EXPECT_LT(hopf_cole_predicted_break(1024, 1e-3), 30.0);
}

TEST(BenchStability, CollapseDetectedForThreeParticlesAtSmallR) {
  EXPECT_EQ(three_particle_stop(0.05).reason, particles::StopReason::collapse);  // r < 7 - 4 sqrt 3
  EXPECT_EQ(three_particle_stop(0.1).reason, particles::StopReason::completed);  // r > 7 - 4 sqrt 3
  EXPECT_NEAR(collapse_particles_predicted(0.9), std::log(10.0) / 0.1, 1e-9);    // -ln(1-r)/(1-r)
}

TEST(BenchStability, MinmodMusclHancockIsTvdUpToOne) {
  // Minmod keeps MUSCL-Hancock TVD up to Courant number 1 on this problem (the
  // bench finds the steeper limiters failing earlier: docs/performance.md).
  const auto lim =
      cfl_limit(cfl_scan(problem_by_name("sine_post"), "godunov2", "minmod", 128, {0.9, 1.0, 1.1, 1.2}));
  EXPECT_EQ(lim.last_stable, 1.0);
  EXPECT_GT(lim.first_failed, 1.0);
}

TEST(BenchStability, CollapseDetectedOnARingAboveTheCriticalSize) {
  // r = 0.5: McNamara-Young N_c ~ 1.4; random ring data collapse from N ~ 12
  // (the bench's scan), and 3 particles on a ring do not within t = 1000.
  EXPECT_EQ(ring_stop(64, 0.5, 100, 1000.0).reason, particles::StopReason::collapse);
  EXPECT_EQ(ring_stop(3, 0.5, 100, 1000.0).reason, particles::StopReason::completed);
}

TEST(BenchCommon, ShockPositionErrorIsTheShiftOfTheCrossing) {
  // A step 1 -> 0 at x = 0.5 on 16 cells, and the same step one cell later: the
  // crossing of v_mid = 0.5 moves by exactly one cell width (linear interpolation).
  std::vector<double> exact(16, 0.0), shifted(16, 0.0);
  for (std::size_t i = 0; i < 8; ++i) exact[i] = 1.0;
  for (std::size_t i = 0; i < 9; ++i) shifted[i] = 1.0;
  EXPECT_NEAR(shock_position_error(shifted, exact, 1.0, 0.5, 0.5, 0.1), 1.0 / 16, 1e-15);
  EXPECT_EQ(shock_position_error(exact, exact, 1.0, 0.5, 0.5, 0.1), 0.0);
  EXPECT_TRUE(
      std::isnan(shock_position_error(exact, exact, 1.0, 0.1, 0.5, 0.1)));  // no crossing near x = 0.1
}

TEST(BenchStability, CsvWritesNonFiniteAsEmptyCell) {
  const std::string path =
      testing_support::process_temp_path("shockgas_bench_csv_test-", "table.csv").string();
  {
    CsvWriter csv(path, {"a", "b", "c"});
    csv << 1.5 << NAN << "x, y";
    csv.end_row();
    EXPECT_THROW(csv.end_row(), RunError);  // wrong number of cells in a row
  }
  std::ifstream in(path);
  std::string header, row;
  std::getline(in, header);
  std::getline(in, row);
  EXPECT_EQ(header, "a,b,c");
  EXPECT_EQ(row, "1.5,,\"x, y\"");
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace shockgas::studies
