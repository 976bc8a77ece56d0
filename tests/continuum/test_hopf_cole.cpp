// Hopf-Cole: exactness of both paths on a closed-form solution, agreement of the
// paths, detected failure of the fft path, convergence to Hopf-Lax as nu -> 0.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "shockgas/continuum/hopf_cole.hpp"
#include "shockgas/continuum/hopf_lax.hpp"
#include "shockgas/core/error.hpp"

namespace sc = shockgas::continuum;
using shockgas::InitialField;
using std::numbers::pi;

namespace {

// theta = 1 + a exp(-nu k^2 t) cos(k y), k = 2 pi / L, solves the heat equation, so
// w = -2 nu (ln theta)_y solves viscous Burgers with zero mean, and
// v(x, t) = U + w(x - U t, t) with mean U. Cell averages from ln theta at the edges.
struct CosineSolution {
  double a = 0.9, nu = 0.05, U = 0.7, L = 1.0;
  double k() const { return 2 * pi / L; }
  double log_theta(double y, double t) const {
    return std::log1p(a * std::exp(-nu * k() * k() * t) * std::cos(k() * y));
  }
  double v0(double x) const { return U + 2 * nu * a * k() * std::sin(k() * x) / (1 + a * std::cos(k() * x)); }
  std::vector<double> cell_averages(std::size_t cells, double t) const {
    const double h = L / static_cast<double>(cells);
    std::vector<double> v(cells);
    for (std::size_t i = 0; i < cells; ++i) {
      const double xa = static_cast<double>(i) * h - U * t, xb = xa + h;
      v[i] = U - 2 * nu * (log_theta(xb, t) - log_theta(xa, t)) / h;
    }
    return v;
  }
};

InitialField sine_field() {
  InitialField f;
  f.length = 1.0;
  f.v0 = [](double x) { return 0.5 + std::sin(2 * pi * x); };
  f.rho0 = [](double) { return 1.0; };
  return f;
}

double max_diff(const std::vector<double>& a, const std::vector<double>& b) {
  double m = 0;
  for (std::size_t i = 0; i < a.size(); ++i) m = std::max(m, std::abs(a[i] - b[i]));
  return m;
}

double l1_diff(const std::vector<double>& a, const std::vector<double>& b, double h) {
  double s = 0;
  for (std::size_t i = 0; i < a.size(); ++i) s += std::abs(a[i] - b[i]) * h;
  return s;
}

// The exact inviscid limit (Hopf-Lax) of the same data, cell averages of v.
std::vector<double> hopf_lax_sine(std::size_t cells, double t) {
  return sc::exact_cell_averages(sine_field(), cells, t).v;
}

}  // namespace

TEST(HopfCole, FftPathIsExactOnTheCosineSolutionWithMeanFlow) {
  const CosineSolution s;
  InitialField f;
  f.v0 = [&](double x) { return s.v0(x); };
  sc::ContinuumParams p;
  p.nu = s.nu;
  p.cells = 256;
  p.hopf_cole_path = sc::HopfColePath::fft;
  const double t = 0.4;
  const sc::ContinuumResult r = sc::solve_hopf_cole(f, p, t);
  // theta0 = 1 + a cos kx exactly, so the spectral solve is exact: only rounding
  // (the 6-point Gauss cell averages of v0 and ~log2(n) eps from FFTW) remains,
  // amplified by 2 nu / h = 25.6; measured 1.5e-14, bound 1e-11.
  EXPECT_LT(max_diff(r.v, s.cell_averages(p.cells, t)), 1e-11);
  EXPECT_EQ(r.stats.at("log_path"), 0.0);
  EXPECT_NE(r.method_note.find("fft path"), std::string::npos);
}

TEST(HopfCole, LogPathIsExactOnTheCosineSolutionWithMeanFlow) {
  const CosineSolution s;
  InitialField f;
  f.v0 = [&](double x) { return s.v0(x); };
  sc::ContinuumParams p;
  p.nu = s.nu;
  p.cells = 256;
  p.hopf_cole_path = sc::HopfColePath::log;
  const double t = 0.4;
  const sc::ContinuumResult r = sc::solve_hopf_cole(f, p, t);
  // Trapezoid sum of the periodised kernel over a trigonometric polynomial of
  // degree 1: exact up to the Gaussian's aliasing exp(-(2 pi / h)^2 nu t) = 0 in
  // double; same rounding budget as the fft test. Measured 1.0e-13.
  EXPECT_LT(max_diff(r.v, s.cell_averages(p.cells, t)), 1e-11);
  EXPECT_EQ(r.stats.at("log_path"), 1.0);
  EXPECT_NE(r.method_note.find("log-domain"), std::string::npos);
}

TEST(HopfCole, PathsAgreeWhereBothWork) {
  // nu = 0.02: DeltaPsi / 2 nu = 8, the fft path keeps ~12 digits of theta.
  const sc::MovingFramePotential psi0 =
      sc::moving_frame_potential(sc::cell_averages(sine_field(), 1024).v, 1.0);
  const double nu = 0.02, t = 0.3, shift = psi0.mean_velocity * t;
  const auto fft = sc::log_theta_fft(psi0, nu, t, shift);
  const auto log = sc::log_theta_kernel(psi0, nu, t, shift);
  const auto v_fft = sc::velocity_from_log_theta(psi0, fft.values, nu);
  const auto v_log = sc::velocity_from_log_theta(psi0, log.values, nu);
  // Measured 1.3e-12 (bound 7.2e-11); the fft roundoff bound is the tolerance (both paths are exact
  // heat solutions of the same nodal data up to the kernel's aliasing, ~e^-600 here).
  EXPECT_LT(max_diff(v_fft, v_log), std::max(fft.velocity_error_bound, 1e-12));
  EXPECT_LT(fft.velocity_error_bound, 1e-9);
}

TEST(HopfCole, FftRoundoffBoundCoversTheMeasuredError) {
  // nu = 0.006: DeltaPsi / 2 nu = 26.5, the fft path has lost ~11 digits of theta
  // near its minimum but is not garbage; the log path is the reference.
  // Measured error 4.2e-4 in v, bound 1.6e-2 (the bound is ~40x conservative).
  const sc::MovingFramePotential psi0 =
      sc::moving_frame_potential(sc::cell_averages(sine_field(), 1024).v, 1.0);
  const double nu = 0.006, t = 0.05, shift = psi0.mean_velocity * t;
  const auto fft = sc::log_theta_fft(psi0, nu, t, shift);
  const auto log = sc::log_theta_kernel(psi0, nu, t, shift);
  const double err = max_diff(sc::velocity_from_log_theta(psi0, fft.values, nu),
                              sc::velocity_from_log_theta(psi0, log.values, nu));
  EXPECT_GT(err, 0.0);
  EXPECT_LE(err, fft.velocity_error_bound);
}

TEST(HopfCole, ForcedFftPathFailsLoudlyForSmallViscosity) {
  sc::ContinuumParams p;
  p.cells = 512;
  p.hopf_cole_path = sc::HopfColePath::fft;
  for (double nu : {1e-3, 1e-4}) {  // DeltaPsi / 2 nu = 159 and 1592 (past exp's range)
    p.nu = nu;
    EXPECT_THROW(sc::solve_hopf_cole(sine_field(), p, 0.3), shockgas::RunError) << "nu = " << nu;
  }
}

TEST(HopfCole, AutoFallsBackToLogPathFarBeyondFftRange) {
  sc::ContinuumParams p;
  p.cells = 1024;
  p.nu = 1e-6;  // DeltaPsi / 2 nu = 1.6e5
  const double t = 0.3;
  const sc::ContinuumResult r = sc::solve_hopf_cole(sine_field(), p, t);
  EXPECT_EQ(r.stats.at("log_path"), 1.0);
  EXPECT_NE(r.method_note.find("rejected"), std::string::npos);
  ASSERT_EQ(r.v.size(), p.cells);
  for (double v : r.v) ASSERT_TRUE(std::isfinite(v));
  // At nu = 1e-6 Hopf-Cole is Hopf-Lax up to L1 ~ C nu, C = 3.4 measured in the
  // convergence test below; measured 4.9e-6 here. Bound: 6 C nu (margin for the
  // O(h^2) difference between piecewise-linear and exact Psi0).
  const double l1 = l1_diff(r.v, hopf_lax_sine(p.cells, t), 1.0 / 1024);
  std::printf("nu = 1e-6, %zu cells: L1(Hopf-Cole - Hopf-Lax) = %.3e\n", p.cells, l1);
  EXPECT_LT(l1, 2e-5);
}

TEST(HopfCole, ConvergesToHopfLaxAtRateOneInViscosity) {
  sc::ContinuumParams p;
  p.cells = 2048;
  const double t = 0.3, h = 1.0 / 2048;
  const std::vector<double> exact = hopf_lax_sine(p.cells, t);
  std::vector<double> err;
  for (double nu : {4e-3, 1e-3, 2.5e-4}) {
    p.nu = nu;
    err.push_back(l1_diff(sc::solve_hopf_cole(sine_field(), p, t).v, exact, h));
  }
  // L1(v_nu - v_0) = O(nu): the viscous shock has width ~ nu / jump, the smooth
  // part Phi_nu - Phi = O(nu log nu) in the potential (Laplace's method). Measured
  // rates ~1.0 (printed below); the grid adds only O(h^2) ~ 2e-7 to each error.
  for (std::size_t k = 1; k < err.size(); ++k) {
    const double rate = std::log(err[k - 1] / err[k]) / std::log(4.0);
    std::printf("nu step %zu: L1 %.3e -> %.3e, rate %.3f\n", k, err[k - 1], err[k], rate);
    EXPECT_GT(rate, 0.85);
    EXPECT_LT(rate, 1.15);
  }
}

TEST(HopfCole, RefusesBadInput) {
  sc::ContinuumParams p;
  p.nu = -1e-3;
  try {
    sc::solve_hopf_cole(sine_field(), p, 0.1);
    FAIL() << "negative nu accepted";
  } catch (const shockgas::InputError& e) {
    EXPECT_EQ(e.key(), "continuum.nu");
  }
  p.nu = 1e-3;
  // A path is named through its declaration (shockgas/continuum/params.cpp): an unknown name is refused
  // there.
  try {
    sc::parameters().set(p, "hopf_cole_path", shockgas::ParameterValue::of("spectral"));
    FAIL() << "unknown path accepted";
  } catch (const shockgas::InputError& e) {
    EXPECT_EQ(e.key(), "continuum.hopf_cole_path");
  }
}

TEST(HopfCole, AutoKeepsAnUsableFftResultWhenTheLogPathIsTooDear) {
  // 2^15 cells at nu = 1e-2: the log path would sum ~1.5e9 kernel terms; the fft
  // bound (~8e-7) is above rtol * max|v0| = 1.5e-8 but far below the 1e-3 * max|v0|
  // at which the fft result is never returned.
  sc::ContinuumParams p;
  p.nu = 1e-2;
  p.cells = 1 << 15;
  p.rtol = 1e-8;
  const sc::ContinuumResult r = sc::solve_hopf_cole(sine_field(), p, 0.3);
  EXPECT_EQ(r.stats.at("log_path"), 0.0);
  EXPECT_GT(r.stats.at("fft_velocity_error_bound"), p.rtol * 1.5);
  EXPECT_NE(r.method_note.find("above tolerance"), std::string::npos) << r.method_note;
}

// At large nu (exp(-Psi / 2 nu) within a factor e of 1) the log path has no
// edge over the fft path and no bound of its own: auto keeps the usable fft
// result, and where even that has lost its digits the solve fails (found:
// nu = 1e7 and 1e10 on a sine of 64 cells gave |v| = 9e-5 and 0.02 by the log
// path where the solution has decayed to 0).
TEST(HopfCole, AtLargeViscosityAutoKeepsTheFftPathOrFails) {
  InitialField f;
  f.length = 1.0;
  f.v0 = [](double x) { return std::sin(2 * pi * x); };
  f.rho0 = [](double) { return 1.0; };
  sc::ContinuumParams p;
  p.cells = 64;
  p.nu = 1e7;
  const sc::ContinuumResult r = sc::solve_hopf_cole(f, p, 0.1);
  EXPECT_EQ(r.stats.at("log_path"), 0.0);
  for (const double v : r.v) EXPECT_LE(std::abs(v), r.stats.at("fft_velocity_error_bound"));  // exact: 0
  p.nu = 1e10;  // the fft bound 4e-3 is above the 1e-3 max|v0| at which a result is never returned
  EXPECT_THROW(sc::solve_hopf_cole(f, p, 0.1), shockgas::RunError);
  // Spread 0: solved exactly, at any nu, by the log path (the fft bound is above
  // rtol * max|v0| = 0). That path sums, for each cell, every node within
  // sqrt(2 t 2 nu 40) = 4e5 lengths at dq = h: 8e5 cells^2 terms, 3.3e9 at 64
  // cells (30 CPU-seconds), 5e7 at the 8 cells (the least allowed) taken here.
  // Each cell's sum runs over the same offsets in the same order whatever the
  // count, so 8 cells check the same exact zero on the same branch.
  p.cells = 8;
  f.v0 = [](double) { return 0.0; };
  const sc::ContinuumResult constant = sc::solve_hopf_cole(f, p, 0.1);
  EXPECT_EQ(constant.stats.at("log_path"), 1.0);
  for (const double v : constant.v) EXPECT_EQ(v, 0.0);
}
