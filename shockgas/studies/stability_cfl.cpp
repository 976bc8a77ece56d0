// Godunov and MUSCL-Hancock against the Courant number (stability.hpp).
// Both are TVD for Courant numbers <= 1 (godunov_scheme.hpp: Godunov 1959; Sweby
// 1984 for the limited second-order scheme), so the predicted limit is 1. The
// steps are taken here, on the same grid class the solvers use, so that the total
// variation is watched after every step: beyond the limit the first sign is a TV
// rise where the fastest cells sit, long before anything blows up, and a final
// state alone would hide it behind the TV the shocks destroy.
#include <algorithm>
#include <cmath>

#include "shockgas/continuum/burgers_physics.hpp"
#include "shockgas/continuum/explicit_viscous.hpp"
#include "shockgas/continuum/godunov_scheme.hpp"
#include "shockgas/continuum/hopf_lax.hpp"
#include "shockgas/continuum/limiters.hpp"
#include "shockgas/studies/stability.hpp"

namespace shockgas::studies {

namespace {

using continuum::BurgersContinuity;
using Grid = continuum::FiniteVolumeGrid<BurgersContinuity>;

constexpr double kTvRise = 1e-8;          // relative TV rise per step that counts (rounding: ~1e-14)
constexpr double kBlowUp = 10.0;          // |v| > 10 max|v0|: blown up, stop
constexpr std::size_t kStepFactor = 100;  // step budget: 100 times the steps at the nominal dt

struct Watch {
  double tv0 = 0, v0max = 0;
  CflPoint pt;
};

// Observes the grid after a step; returns false once it has blown up.
bool observe(const Grid& g, double tv_before, Watch& w, double& tv_after) {
  std::vector<double> v(g.size());
  double vmax = 0;
  bool finite = true;
  for (std::size_t i = 0; i < g.size(); ++i) {
    v[i] = g.cell(i)[0];
    finite = finite && std::isfinite(v[i]) && std::isfinite(g.cell(i)[1]);
    vmax = std::max(vmax, std::abs(v[i]));
    w.pt.min_rho = std::min(w.pt.min_rho, g.cell(i)[1]);
  }
  if (!finite || vmax > kBlowUp * w.v0max) return w.pt.blew_up = true, false;
  tv_after = continuum::periodic_total_variation(v);
  const double rise = (tv_after - tv_before) / w.tv0;
  w.pt.max_tv_rise = std::max(w.pt.max_tv_rise, rise);
  if (rise > kTvRise) ++w.pt.rising_steps;
  return true;
}

template <class StepFn>
void run(Grid& g, double cfl, double t_end, Watch& w, StepFn&& step) {
  const std::size_t budget = kStepFactor * std::size_t(std::ceil(t_end * w.v0max / (cfl * g.dx())) + 1);
  double t = 0, tv = w.tv0, speed = w.v0max;
  for (std::size_t n = 0; t < t_end && n < budget; ++n) {
    const double dt = std::min(cfl * g.dx() / speed, t_end - t);
    speed = step(dt).max_speed;
    t = dt >= t_end - t ? t_end : t + dt;
    w.pt.t_reached = t;
    if (!observe(g, tv, w, tv) || !(speed > 0)) return;
  }
}

void describe(CflPoint& pt) {
  pt.failed = pt.blew_up || pt.rising_steps > 0;
  if (pt.blew_up)
    pt.what = "blew up at t = " + fmt(pt.t_reached) + " (|v| > 10 max|v0| or non-finite)";
  else if (pt.failed)
    pt.what = "total variation rose in " + std::to_string(pt.rising_steps) + " steps (max rise " +
              fmt(pt.max_tv_rise) + " TV0); end: TV x" + fmt(pt.tv_ratio) + ", max|v| x" + fmt(pt.max_ratio);
  else
    pt.what = "TVD (no step raised TV)";
  if (pt.min_rho < 0) pt.what += "; density went negative (min " + fmt(pt.min_rho) + ")";
}

CflPoint scan_point(const Problem& pb, const std::string& solver, continuum::Limiter limiter,
                    std::size_t cells, double cfl, const continuum::CellAverages& v0,
                    const continuum::CellAverages& exact) {
  std::vector<BurgersContinuity::State> u(cells);
  for (std::size_t i = 0; i < cells; ++i) u[i] = {v0.v[i], v0.rho[i]};
  Grid g(u, pb.field.length / double(cells), continuum::Boundary::periodic);
  Watch w;
  w.pt.cfl = cfl;
  w.tv0 = continuum::periodic_total_variation(v0.v);
  for (double x : v0.v) w.v0max = std::max(w.v0max, std::abs(x));
  w.pt.min_rho = *std::min_element(v0.rho.begin(), v0.rho.end());
  if (solver == solver_names().godunov) {
    run(g, cfl, pb.t, w, [&](double dt) { return g.step_godunov(dt); });
  } else {
    continuum::with_limiter(limiter, [&](auto lim) {
      run(g, cfl, pb.t, w, [&](double dt) { return g.template step_muscl_hancock<decltype(lim)>(dt); });
    });
  }
  if (w.pt.blew_up) {  // no end state to measure: empty cells, not numbers
    w.pt.tv_ratio = w.pt.max_ratio = w.pt.l1 = NAN;
  } else {
    std::vector<double> v(cells);
    for (std::size_t i = 0; i < cells; ++i) v[i] = g.cell(i)[0];
    w.pt.tv_ratio = continuum::periodic_total_variation(v) / w.tv0;
    w.pt.max_ratio =
        *std::max_element(v.begin(), v.end(), [](double a, double b) { return std::abs(a) < std::abs(b); });
    w.pt.max_ratio = std::abs(w.pt.max_ratio) / w.v0max;
    w.pt.l1 = error_norms(v, exact.v, g.dx()).l1;
  }
  describe(w.pt);
  return w.pt;
}

}  // namespace

std::vector<CflPoint> cfl_scan(const Problem& pb, const std::string& solver, const std::string& limiter,
                               std::size_t cells, const std::vector<double>& cfls) {
  const auto lim = parse_enum<continuum::Limiter>(limiter, "continuum.limiter");
  const auto v0 = continuum::cell_averages(pb.field, cells);
  const auto exact = continuum::exact_cell_averages(pb.field, cells, pb.t, {4, 2048, 64});
  std::vector<CflPoint> out;
  for (double c : cfls) out.push_back(scan_point(pb, solver, lim, cells, c, v0, exact));
  return out;
}

ScanLimit cfl_limit(const std::vector<CflPoint>& points) {
  ScanLimit s;
  for (const auto& pt : points) {
    if (pt.failed) return s.first_failed = pt.cfl, s;
    s.last_stable = pt.cfl;
  }
  return s;
}

void cfl_stability(const Context& ctx, FailureLog& failures) {
  CsvWriter csv(ctx.path("stability_cfl.csv"),
                {"problem", "method", "cfl", "failed", "max_tv_rise", "rising_steps", "tv_ratio", "max_ratio",
                 "min_rho", "l1", "what"});
  CsvWriter limits(ctx.path("stability_cfl_limits.csv"),
                   {"problem", "method", "predicted", "last_stable", "first_failed"});
  const std::size_t cells = ctx.full ? 1024 : 256;
  const std::vector<double> cfls =
      ctx.full ? std::vector<double>{0.5, 0.7,  0.75, 0.8, 0.85, 0.9, 0.95, 0.98,
                                     1.0, 1.02, 1.05, 1.1, 1.2,  1.3, 1.5,  2.0}
               : std::vector<double>{0.5, 0.8, 0.85, 0.9, 0.95, 1.0, 1.05, 1.1, 1.2, 1.5, 2.0};
  for (const Problem& pb : {problem_by_name("sine_post"), problem_by_name("noise")}) {
    for (std::string limiter : {"", "minmod", "vanleer", "mc"}) {
      const auto& names = solver_names();
      const std::string method = limiter.empty() ? names.godunov : names.godunov2 + " (" + limiter + ")";
      ctx.log("stability", "CFL scan of " + method + ", " + pb.name);
      const auto points = cfl_scan(pb, limiter.empty() ? names.godunov : names.godunov2,
                                   limiter.empty() ? "mc" : limiter, cells, cfls);
      for (const auto& pt : points) {
        csv << pb.name << method << pt.cfl << (pt.failed ? "yes" : "no") << pt.max_tv_rise
            << double(pt.rising_steps) << pt.tv_ratio << pt.max_ratio << pt.min_rho << pt.l1 << pt.what;
        csv.end_row();
      }
      const ScanLimit lim = cfl_limit(points);
      limits << pb.name << method << 1.0 << lim.last_stable << lim.first_failed;
      limits.end_row();
      if (lim.first_failed > 0) {
        const auto& pt =
            *std::find_if(points.begin(), points.end(), [](const CflPoint& p) { return p.failed; });
        failures.add({"cfl", method, pb.name + ", " + std::to_string(cells) + " cells, cfl = " + fmt(pt.cfl),
                      "first failure of the scan (last stable " + fmt(lim.last_stable) +
                          ", predicted 1): " + pt.what});
      }
    }
  }
}

}  // namespace shockgas::studies
