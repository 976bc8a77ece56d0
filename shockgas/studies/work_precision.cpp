// Work-precision of the continuum solvers (docs/performance.md): for each method
// and setting, the error of the cell averages against the exact solution and the
// median wall time of repeated runs, on the reference problems (problems.hpp).
//
// Two references, never mixed in one chart:
//  * wp_inviscid.csv: the exact inviscid solution (Hopf-Lax cell averages). The
//    viscous Hopf-Cole lines (one point per nu) then show the O(nu) viscous
//    difference itself: their error is what replacing nu -> 0 by a finite nu costs.
//  * wp_viscous.csv: the exact viscous solution at the same nu and grid (Hopf-Cole,
//    log-domain path: exact ln theta of the cell-averaged data), for CVODE and
//    ARKODE over tolerances and Hopf-Cole FFT; their error is discretisation and
//    integration error only.
#include <chrono>
#include <cmath>
#include <string>
#include <vector>

#include "shockgas/continuum/hopf_lax.hpp"
#include "shockgas/continuum/solve.hpp"
#include "shockgas/core/error.hpp"
#include "shockgas/studies/problems.hpp"
#include "shockgas/studies/sections.hpp"

namespace shockgas::studies {

namespace {

using continuum::ContinuumParams;
using continuum::ContinuumResult;

// Exact Hopf-Lax cell averages with every kink of the piecewise data on a node
// (the Riemann and noise data are piecewise constant on 64 equal cells).
continuum::HopfLaxOptions exact_options() { return {4, 2048, 64}; }

struct Setting {
  std::string method;  // line of the chart: "godunov2 (mc)", "hopf_cole fft", ...
  std::string solver;  // continuum::solve name
  ContinuumParams params;
  double parameter = 0;  // what varies along the line (cells, nu or rtol)
};

std::vector<std::size_t> cell_counts(const Context& ctx) {
  if (ctx.full) return {64, 128, 256, 512, 1024, 2048, 4096, 8192, 16384};
  return {64, 128, 256, 512, 1024, 2048};
}

std::vector<Setting> inviscid_settings(const Context& ctx) {
  std::vector<Setting> s;
  for (std::size_t cells : cell_counts(ctx)) {
    ContinuumParams p;
    p.cells = cells;
    const auto& names = solver_names();
    s.push_back({names.godunov, names.godunov, p, double(cells)});
    for (continuum::Limiter lim :
         {continuum::Limiter::minmod, continuum::Limiter::vanleer, continuum::Limiter::mc}) {
      p.limiter = lim;
      s.push_back({names.godunov2 + " (" + name_of(lim) + ")", names.godunov2, p, double(cells)});
    }
    s.push_back({names.hopf_lax + " (exact)", names.hopf_lax, p, double(cells)});
  }
  const std::size_t hc_cells = ctx.full ? 8192 : 2048;
  for (double nu : {1e-2, 3e-3, 1e-3, 3e-4, 1e-4}) {
    ContinuumParams p;
    p.cells = hc_cells;
    p.nu = nu;
    for (continuum::HopfColePath path : {continuum::HopfColePath::fft, continuum::HopfColePath::log}) {
      p.hopf_cole_path = path;
      s.push_back({solver_names().hopf_cole + " " + name_of(path), solver_names().hopf_cole, p, nu});
    }
  }
  return s;
}

std::vector<Setting> viscous_settings(const Context& ctx, double nu) {
  std::vector<Setting> s;
  const std::size_t cells = ctx.full ? 2048 : 256;
  ContinuumParams p;
  p.cells = cells;
  p.nu = nu;
  for (double rtol : {1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7}) {
    p.rtol = rtol;
    s.push_back({solver_names().cvode, solver_names().cvode, p, rtol});
    s.push_back({solver_names().arkode, solver_names().arkode, p, rtol});
  }
  p.rtol = 1e-6;
  p.hopf_cole_path = continuum::HopfColePath::fft;
  s.push_back({solver_names().hopf_cole + " fft", solver_names().hopf_cole, p, double(cells)});
  return s;
}

struct Measured {
  ContinuumResult result;
  double seconds = 0;
};

// Wall budget of one run [s]: a setting whose projected time (elapsed / fraction
// done, at the solver's progress reports) exceeds it is stopped and reported as
// a failure instead of holding up the bench.
double run_budget(const Context& ctx) { return ctx.full ? 120.0 : 3.0; }

ProgressCallback budget_watch(double budget) {
  const auto start = std::chrono::steady_clock::now();
  return [start, budget](double fraction, double, std::uint64_t) {
    const double elapsed = seconds_since(start);
    if (fraction > 0 && elapsed / fraction > budget)
      throw RunError("stopped by the bench: projected " + fmt(elapsed / fraction) + " s per run > budget " +
                     fmt(budget) + " s");
  };
}

// Median wall time of ctx.repeats runs; the result of the last one.
Measured measure(const Context& ctx, const Setting& s, const Problem& pb) {
  Measured m;
  m.seconds = median_seconds(ctx.repeats, [&] {
    m.result = continuum::solve(s.solver, pb.field, s.params, pb.t, budget_watch(run_budget(ctx)));
  });
  return m;
}

// Shock-position error against the exact shocks with a jump above 0.1 (the
// isolated ones): the worst of them; NaN (an empty cell) where not measured or
// where the profile has no crossing near the shock. Burgers: v_mid = shock speed.
double shock_error(const Problem& pb, const ContinuumResult& exact, const std::vector<double>& v) {
  if (!pb.shock_error) return NAN;
  double worst = 0;
  for (const auto& s : exact.shocks)
    if (std::abs(s.jump) > 0.1) {
      const double e = shock_position_error(v, exact.v, exact.length, s.x, s.v, 0.05);
      if (std::isnan(e)) return NAN;
      worst = std::max(worst, e);
    }
  return worst;
}

const std::vector<std::string> kColumns = {"problem", "method",      "parameter", "cells",
                                           "nu",      "rtol",        "reference", "l1",
                                           "linf",    "shock_error", "seconds",   "note"};

void write_row(CsvWriter& csv, const Problem& pb, const Setting& s, const std::string& reference,
               const Norms& e, double shock, double seconds, const std::string& note) {
  const bool viscous = continuum::solver_info(s.solver).viscous;
  const bool adaptive = s.solver == solver_names().cvode || s.solver == solver_names().arkode;
  csv << pb.name << s.method << s.parameter << double(s.params.cells) << (viscous ? s.params.nu : NAN)
      << (adaptive ? s.params.rtol : NAN) << reference << e.l1 << e.linf << shock << seconds << note;
  csv.end_row();
}

// Runs one setting; a failure goes to the log instead of the table.
void run_setting(const Context& ctx, FailureLog& failures, CsvWriter& csv, const Problem& pb,
                 const Setting& s, const ContinuumResult& reference, const std::string& reference_name) {
  try {
    const Measured m = measure(ctx, s, pb);
    const double h = pb.field.length / double(s.params.cells);
    const Norms e = error_norms(m.result.v, reference.v, h);
    const double shock =
        reference_name == solver_names().hopf_lax ? shock_error(pb, reference, m.result.v) : NAN;
    write_row(csv, pb, s, reference_name, e, shock, m.seconds, m.result.method_note);
  } catch (const std::exception& e) {  // InputError (outside the range) or RunError (failed)
    rethrow_if_bench_failure(e);
    failures.add({"work_precision", s.method, pb.name + ", parameter = " + fmt(s.parameter), e.what()});
  }
}

void inviscid(const Context& ctx, FailureLog& failures) {
  CsvWriter csv(ctx.path("wp_inviscid.csv"), kColumns);
  for (const Problem& pb : reference_problems()) {
    ctx.log("work-precision", "inviscid, problem " + pb.name);
    std::size_t cached_cells = 0;
    ContinuumResult exact;
    for (const Setting& s : inviscid_settings(ctx)) {
      if (s.params.cells != cached_cells) {
        exact = continuum::solve_hopf_lax(pb.field, s.params.cells, pb.t, exact_options());
        cached_cells = s.params.cells;
      }
      run_setting(ctx, failures, csv, pb, s, exact, solver_names().hopf_lax);
    }
  }
}

void viscous(const Context& ctx, FailureLog& failures) {
  CsvWriter csv(ctx.path("wp_viscous.csv"), kColumns);
  const double nu = 1e-2;  // resolved by 256 cells: Dv h / nu = 0.8 (viscous_mol.hpp needs <= 2)
  for (const Problem& pb : reference_problems()) {
    ctx.log("work-precision", "viscous (nu = " + fmt(nu) + "), problem " + pb.name);
    const std::vector<Setting> settings = viscous_settings(ctx, nu);
    ContinuumParams ref = settings.front().params;
    ref.hopf_cole_path = continuum::HopfColePath::log;
    const ContinuumResult exact = continuum::solve(solver_names().hopf_cole, pb.field, ref, pb.t);
    for (const Setting& s : settings)
      run_setting(ctx, failures, csv, pb, s, exact, solver_names().hopf_cole + " log");
  }
}

}  // namespace

void continuum_work_precision(const Context& ctx, FailureLog& failures) {
  inviscid(ctx, failures);
  viscous(ctx, failures);
}

}  // namespace shockgas::studies
