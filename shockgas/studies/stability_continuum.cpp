// Stability scans of the continuum methods (stability.hpp); the
// Courant-number scan of the finite-volume schemes is stability_cfl.cpp.
//  * stability_viscous.csv: explicit viscous Burgers against nu, dx and dt (predicted
//    dt <= h^2/2nu / (1 + |v| h/2nu), explicit_viscous.hpp), next to CVODE and ARKODE
//    at the same nu and dx (no step limit: their mean step against h^2/2nu);
//  * stability_hopf_cole.csv: the raw Hopf-Cole FFT path against DeltaPsi/2nu, its
//    error measured against the log-domain path, the solver's own verdict.
#include <algorithm>
#include <cmath>
#include <limits>

#include "shockgas/continuum/explicit_viscous.hpp"
#include "shockgas/continuum/hopf_cole.hpp"
#include "shockgas/continuum/solve.hpp"
#include "shockgas/studies/sections.hpp"
#include "shockgas/studies/stability.hpp"

namespace shockgas::studies {

namespace {

using continuum::ContinuumParams;

constexpr double kGrowthTolerance = 0.01;  // TV growth of 1 %: far above rounding, far below a blow-up

double max_abs(const std::vector<double>& v) {
  double m = 0;
  for (double x : v) m = std::max(m, std::abs(x));
  return m;
}

}  // namespace

ViscousPoint explicit_viscous_point(const Problem& pb, double nu, std::size_t cells, double c,
                                    std::size_t steps) {
  const double h = pb.field.length / double(cells);
  const auto v0 = continuum::cell_averages(pb.field, cells).v;
  continuum::ExplicitViscousParams p;
  p.nu = nu;
  p.dt = c * h * h / (2 * nu);
  p.steps = steps;
  const auto r = continuum::explicit_viscous_burgers(v0, h, p);
  ViscousPoint pt;
  pt.nu = nu, pt.cells = cells, pt.c = c;
  pt.c_predicted = continuum::explicit_viscous_dt_limit(max_abs(v0), h, nu) / (h * h / (2 * nu));
  pt.tv_ratio = r.total_variation / continuum::periodic_total_variation(v0);
  pt.failed = r.blew_up || pt.tv_ratio > 1 + kGrowthTolerance;
  pt.steps = r.steps;
  return pt;
}

double hopf_cole_predicted_break(std::size_t cells, double tolerance) {
  const double eps = std::numeric_limits<double>::epsilon();
  return std::log(tolerance / (eps * std::log2(double(cells))));
}

HopfColePoint hopf_cole_point(const Problem& pb, std::size_t cells, double ratio) {
  const auto v0 = continuum::cell_averages(pb.field, cells).v;
  const auto psi0 = continuum::moving_frame_potential(v0, pb.field.length);
  HopfColePoint pt;
  pt.ratio = ratio;
  pt.nu = psi0.spread() / (2 * ratio);
  const double shift = psi0.mean_velocity * pb.t;
  const auto start = std::chrono::steady_clock::now();
  const auto lt_log = continuum::log_theta_kernel(psi0, pt.nu, pb.t, shift);
  const auto v_log = continuum::velocity_from_log_theta(psi0, lt_log.values, pt.nu);
  pt.log_seconds = seconds_since(start);
  const auto lt_fft = continuum::log_theta_fft(psi0, pt.nu, pb.t, shift);
  const auto v_fft = continuum::velocity_from_log_theta(psi0, lt_fft.values, pt.nu);
  pt.fft_bound = lt_fft.velocity_error_bound;
  pt.fft_finite = std::all_of(v_fft.begin(), v_fft.end(), [](double x) { return std::isfinite(x); });
  pt.fft_error = pt.fft_finite ? error_norms(v_fft, v_log, 1.0).linf : NAN;
  ContinuumParams p;
  p.cells = cells;
  p.nu = pt.nu;
  p.hopf_cole_path = continuum::HopfColePath::fft;
  try {
    const auto r = continuum::solve(solver_names().hopf_cole, pb.field, p, pb.t);
    pt.solver_fft = "accepted: " + r.method_note;
  } catch (const std::exception& e) {
    rethrow_if_bench_failure(e);
    pt.solver_fft = std::string("refused: ") + e.what();
  }
  p.hopf_cole_path = continuum::HopfColePath::automatic;
  try {
    pt.solver_auto = continuum::solve(solver_names().hopf_cole, pb.field, p, pb.t).method_note;
  } catch (const std::exception& e) {
    rethrow_if_bench_failure(e);
    pt.solver_auto = std::string("failed: ") + e.what();
  }
  return pt;
}

namespace {

void explicit_rows(const Context& ctx, CsvWriter& csv, FailureLog& failures, const Problem& pb, double nu,
                   std::size_t cells) {
  const std::size_t steps = ctx.full ? 20000 : 4000;
  bool reported = false;
  for (double c : {0.02, 0.05, 0.1, 0.2, 0.3, 0.5, 0.7, 0.8, 0.9, 0.95, 1.0, 1.05, 1.1, 1.2, 1.5, 2.0}) {
    const ViscousPoint pt = explicit_viscous_point(pb, nu, cells, c, steps);
    const std::string what = pt.failed ? "blew up or TV grew (x" + fmt(pt.tv_ratio) + ") after " +
                                             std::to_string(pt.steps) + " steps"
                                       : "stable";
    csv << "explicit" << nu << double(cells) << c << pt.c_predicted << (pt.failed ? "yes" : "no")
        << pt.tv_ratio << double(pt.steps) << NAN << what;
    csv.end_row();
    if (pt.failed && !reported) {
      reported = true;
      failures.add({"viscous_explicit", "forward Euler (Godunov flux + central diffusion)",
                    "nu = " + fmt(nu) + ", " + std::to_string(cells) + " cells, dt = " + fmt(c) + " h^2/2nu",
                    "first failure: " + what + " (predicted limit " + fmt(pt.c_predicted) + " h^2/2nu)"});
    }
  }
}

void implicit_rows(CsvWriter& csv, FailureLog& failures, const Problem& pb, double nu, std::size_t cells) {
  ContinuumParams p;
  p.cells = cells;
  p.nu = nu;
  p.rtol = 1e-6;
  const double h = pb.field.length / double(cells), limit = h * h / (2 * nu);
  for (const std::string& solver : {solver_names().cvode, solver_names().arkode}) {
    try {
      const auto r = continuum::solve(solver, pb.field, p, pb.t);
      const double steps = r.stats.count("steps") ? r.stats.at("steps") : NAN;
      csv << solver << nu << double(cells) << (pb.t / steps) / limit << NAN << "no" << NAN << steps
          << r.wall_seconds << "completed; mean step = " + fmt(pb.t / steps / limit) + " h^2/2nu";
      csv.end_row();
    } catch (const std::exception& e) {
      rethrow_if_bench_failure(e);
      failures.add({"viscous_implicit", solver, "nu = " + fmt(nu) + ", " + std::to_string(cells) + " cells",
                    e.what()});
      csv << solver << nu << double(cells) << NAN << NAN << "yes" << NAN << NAN << NAN
          << std::string("refused: ") + e.what();
      csv.end_row();
    }
  }
}

void viscous_section(const Context& ctx, FailureLog& failures) {
  CsvWriter csv(ctx.path("stability_viscous.csv"), {"method", "nu", "cells", "c", "c_predicted", "failed",
                                                    "tv_ratio", "steps", "seconds", "what"});
  const Problem pb = problem_by_name("sine_pre");
  for (double nu : {1e-3, 1e-2, 1e-1}) {
    for (std::size_t cells : {64u, 128u, 256u, 512u}) {
      ctx.log("stability", "explicit viscous, nu = " + fmt(nu) + ", " + std::to_string(cells) + " cells");
      explicit_rows(ctx, csv, failures, pb, nu, cells);
      implicit_rows(csv, failures, pb, nu, cells);
    }
  }
}

void hopf_cole_section(const Context& ctx, FailureLog& failures) {
  CsvWriter csv(ctx.path("stability_hopf_cole.csv"), {"ratio", "nu", "fft_error", "fft_finite", "fft_bound",
                                                      "log_seconds", "solver_fft", "solver_auto"});
  const Problem pb = problem_by_name("sine_post");
  const std::size_t cells = ctx.full ? 4096 : 1024;
  const double scale = 1.5, tolerance = 1e-3;  // max|v0|; digits lost = error above 1e-3 max|v0|
  bool lost = false, nonfinite = false;
  for (double ratio : {2.0, 5.0, 10.0, 15.0, 20.0, 25.0, 30.0, 35.0, 40.0, 50.0, 70.0, 100.0, 200.0, 400.0,
                       700.0, 750.0, 1000.0, 1500.0}) {
    ctx.log("stability", "Hopf-Cole FFT, DeltaPsi/2nu = " + fmt(ratio));
    const HopfColePoint pt = hopf_cole_point(pb, cells, ratio);
    csv << pt.ratio << pt.nu << pt.fft_error << (pt.fft_finite ? "yes" : "no") << pt.fft_bound
        << pt.log_seconds << pt.solver_fft << pt.solver_auto;
    csv.end_row();
    const std::string where =
        "DeltaPsi/2nu = " + fmt(ratio) + " (nu = " + fmt(pt.nu) + ", " + std::to_string(cells) + " cells)";
    if (!lost && (!pt.fft_finite || pt.fft_error > tolerance * scale)) {
      lost = true;
      failures.add({"hopf_cole_fft", "hopf_cole fft (raw)", where,
                    "digits lost: error " + (pt.fft_finite ? fmt(pt.fft_error) : std::string("non-finite")) +
                        " > 1e-3 max|v0| (roundoff prediction: ratio " +
                        fmt(hopf_cole_predicted_break(cells, tolerance)) + "; exp range: ~709)"});
    }
    if (!nonfinite && !pt.fft_finite) {
      nonfinite = true;
      failures.add({"hopf_cole_fft", "hopf_cole fft (raw)", where,
                    "non-finite velocities (theta underflowed or went negative)"});
    }
  }
}

}  // namespace

void continuum_stability(const Context& ctx, FailureLog& failures) {
  cfl_stability(ctx, failures);
  viscous_section(ctx, failures);
  hopf_cole_section(ctx, failures);
}

}  // namespace shockgas::studies
