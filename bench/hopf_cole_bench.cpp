// Hopf-Cole speed (target: the FFT path on 2^20 points in well under a second).
//
// Problem: v0 = 0.5 + sin 2 pi x on [0, 1), t = 0.3 (after the shock forms).
//  * BM_HopfColeFft/n: the fft path (theta0, r2c, heat propagator and shift, c2r,
//    ln theta, velocities) on n points at nu = 1e-2 (DeltaPsi / 2 nu = 16, within its range).
//  * BM_HopfColeSolve/n: the whole solve_hopf_cole (cell averages of v0 by 6-point Gauss
//    included), path chosen automatically (fft here).
//  * Baseline BM_HopfColeKernel/n: the log-domain heat-kernel sum on the same problem,
//    O(n * window) with a window of ~0.7 n nodes at this nu: the direct evaluation the
//    FFT replaces. Compare BM_HopfColeKernel/4096 with BM_HopfColeFft/4096.
//  * BM_HopfColeKernelSmallNu/n: the log path where it is needed (nu = 1e-7,
//    DeltaPsi / 2 nu = 1.6e6, far past the fft path's range; window ~900 nodes at n = 2^16).
#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>

#include "shockgas/continuum/hopf_cole.hpp"

namespace sc = shockgas::continuum;

namespace {

constexpr double kTime = 0.3;

shockgas::InitialField sine_field() {
  shockgas::InitialField f;
  f.v0 = [](double x) { return 0.5 + std::sin(2 * std::numbers::pi * x); };
  f.rho0 = [](double) { return 1.0; };
  return f;
}

sc::MovingFramePotential sine_potential(std::size_t n) {
  return sc::moving_frame_potential(sc::cell_averages(sine_field(), n).v, 1.0);
}

void run_path(benchmark::State& state, double nu, bool fft) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const sc::MovingFramePotential psi0 = sine_potential(n);
  const double shift = psi0.mean_velocity * kTime;
  for (auto _ : state) {
    const sc::LogTheta lt =
        fft ? sc::log_theta_fft(psi0, nu, kTime, shift) : sc::log_theta_kernel(psi0, nu, kTime, shift);
    benchmark::DoNotOptimize(sc::velocity_from_log_theta(psi0, lt.values, nu));
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * n));
}

void BM_HopfColeFft(benchmark::State& state) { run_path(state, 1e-2, true); }
void BM_HopfColeKernel(benchmark::State& state) { run_path(state, 1e-2, false); }
void BM_HopfColeKernelSmallNu(benchmark::State& state) { run_path(state, 1e-7, false); }

void BM_HopfColeSolve(benchmark::State& state) {
  sc::ContinuumParams p;
  p.nu = 1e-2;
  p.cells = static_cast<std::size_t>(state.range(0));
  const auto f = sine_field();
  for (auto _ : state) benchmark::DoNotOptimize(sc::solve_hopf_cole(f, p, kTime));
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * p.cells));
}

}  // namespace

BENCHMARK(BM_HopfColeFft)->Arg(1 << 12)->Arg(1 << 16)->Arg(1 << 20)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_HopfColeSolve)->Arg(1 << 20)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_HopfColeKernel)->Arg(1 << 12)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_HopfColeKernelSmallNu)->Arg(1 << 16)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
