// Work-precision of the particle engine (docs/performance.md):
//  * particles_cost.csv: wall time against N at a fixed time, and against the
//    number of collisions per particle at a fixed N (t_end grows); the cost per
//    collision is the engine's figure of merit;
//  * particles_statistics.csv: the statistical error of T(t_end) and of the
//    fitted late-time exponent (T ~ t^alpha, alpha -> -2/3) against the CPU time
//    spent, as the realizations grow (R = 1, 2, 4, ...). The error of the mean of
//    T is the standard error over realizations; the exponent's is the jackknife
//    error of the exponent fitted to the ensemble mean (leave one realization out:
//    sqrt((R-1)/R sum (alpha_(i) - mean)^2); Efron & Tibshirani 1993, ch. 11), which
//    unlike the spread of single-realization fits is not dominated by the few
//    realizations whose late T(t) is ruled by one or two clusters.
#include <cmath>
#include <numeric>
#include <vector>

#include "shockgas/compare/cooling_law.hpp"
#include "shockgas/core/initial_condition.hpp"
#include "shockgas/particles/simulate.hpp"
#include "shockgas/studies/sections.hpp"

namespace shockgas::studies {

namespace {

using particles::ParticleParams;
using particles::RunResult;

constexpr double kRestitution = 0.5;  // eps = 0.25: sticky regime from t_stick = eps^-1.5 = 8
constexpr double kDelta = 1e-2;       // the paper's threshold

ParticleParams gas_params(double t_end, std::size_t samples, double max_wall) {
  ParticleParams p;
  p.r = kRestitution;
  p.delta = kDelta;
  p.t_end = t_end;
  p.samples = samples;
  p.clusters = false;
  p.threads = 1;
  p.max_wall_seconds = max_wall;
  return p;
}

Bodies gas(std::size_t N, std::uint64_t realization) {
  InitialParams ip;
  ip.N = N;
  ip.seed = 7;
  return make_initial_bodies(ip, realization);
}

void cost_row(CsvWriter& csv, const std::string& scan, std::size_t N, double t_end, const RunResult& r,
              double seconds) {
  const double per_particle = double(r.collisions) / double(N);
  csv << scan << double(N) << t_end << double(r.collisions) << per_particle << seconds
      << (r.collisions > 0 ? 1e9 * seconds / double(r.collisions) : NAN)
      << particles::to_string(r.stop.reason);
  csv.end_row();
}

// One measured point: median wall time of ctx.repeats identical runs.
void cost_point(const Context& ctx, FailureLog& failures, CsvWriter& csv, const std::string& scan,
                std::size_t N, double t_end) {
  const Bodies b = gas(N, 0);
  const ParticleParams p = gas_params(t_end, 4, ctx.full ? 600.0 : 20.0);
  RunResult r;
  const double s = median_seconds(ctx.repeats, [&] { r = particles::simulate(b, double(N), p); });
  if (r.stop.reason != particles::StopReason::completed)
    failures.add({"particles_cost", "events (r = 0.5, delta = 0.01)",
                  "N = " + fmt(double(N)) + ", t_end = " + fmt(t_end),
                  "stopped early: " + particles::to_string(r.stop.reason) + " at t = " + fmt(r.stop.time)});
  cost_row(csv, scan, N, t_end, r, s);
}

void cost(const Context& ctx, FailureLog& failures) {
  CsvWriter csv(
      ctx.path("particles_cost.csv"),
      {"scan", "N", "t_end", "collisions", "collisions_per_particle", "seconds", "ns_per_collision", "stop"});
  const std::vector<double> sizes =
      ctx.full ? std::vector<double>{1e3, 1e4, 1e5, 1e6} : std::vector<double>{1e3, 3e3, 1e4, 3e4, 1e5};
  for (double N : sizes) {
    ctx.log("particles", "cost, N = " + fmt(N));
    cost_point(ctx, failures, csv, "N", std::size_t(N), 100.0);
  }
  const std::size_t N = ctx.full ? 100000 : 10000;
  for (double t_end : {10.0, 30.0, 100.0, 300.0, 1000.0, 3000.0}) {
    ctx.log("particles", "cost, N = " + fmt(double(N)) + ", t_end = " + fmt(t_end));
    cost_point(ctx, failures, csv, "collisions", N, t_end);
  }
}

struct Realization {
  std::vector<double> t, T;
  double seconds = 0;
};

double mean(const std::vector<double>& x) {
  return std::accumulate(x.begin(), x.end(), 0.0) / double(x.size());
}

double standard_error(const std::vector<double>& x) {
  if (x.size() < 2) return NAN;
  const double m = mean(x);
  double s = 0;
  for (double v : x) s += (v - m) * (v - m);
  return std::sqrt(s / double(x.size() - 1) / double(x.size()));
}

// Mean T(t) over runs[0..n) except `skip` (n to skip none).
std::vector<double> mean_T(const std::vector<Realization>& runs, std::size_t n, std::size_t skip) {
  std::vector<double> m(runs[0].T.size(), 0.0);
  const double count = double(skip < n ? n - 1 : n);
  for (std::size_t k = 0; k < n; ++k)
    if (k != skip)
      for (std::size_t i = 0; i < m.size(); ++i) m[i] += runs[k].T[i] / count;
  return m;
}

// Jackknife error of the exponent fitted to the mean of runs[0..n); NaN for n < 2.
double jackknife_exponent_error(const std::vector<Realization>& runs, std::size_t n, double t_fit,
                                double t_end) {
  if (n < 2) return NAN;
  std::vector<double> a;
  for (std::size_t skip = 0; skip < n; ++skip)
    a.push_back(compare::fit_power_law(runs[0].t, mean_T(runs, n, skip), t_fit, t_end).exponent);
  const double m = mean(a);
  double s = 0;
  for (double v : a) s += (v - m) * (v - m);
  return std::sqrt(double(n - 1) / double(n) * s);
}

void statistics(const Context& ctx, FailureLog& failures) {
  const std::size_t N = ctx.full ? 10000 : 2000, R = ctx.full ? 128 : 32;
  const double t_end = ctx.full ? 1e4 : 1e3, t_fit = 30.0;  // fit window [30, t_end]: past t_stick = 8
  ctx.log("particles", "statistics, " + std::to_string(R) + " realizations of N = " + std::to_string(N));
  std::vector<Realization> runs;
  for (std::size_t k = 0; k < R; ++k) {
    const RunResult r = particles::simulate(gas(N, k), double(N), gas_params(t_end, 30, 60.0));
    if (r.stop.reason != particles::StopReason::completed) {
      failures.add({"particles_statistics", solver_names().events, "realization " + std::to_string(k),
                    "stopped early: " + particles::to_string(r.stop.reason)});
      continue;
    }
    runs.push_back({r.series.t, r.series.T, r.wall_seconds});
  }
  if (runs.empty()) return;
  CsvWriter csv(ctx.path("particles_statistics.csv"),
                {"realizations", "cpu_seconds", "T_end", "T_end_rel_error", "exponent", "exponent_error",
                 "exponent_fit_error"});
  for (std::size_t n = 1; n <= runs.size(); n *= 2) {
    std::vector<double> T_end;
    double cpu = 0;
    for (std::size_t k = 0; k < n; ++k) {
      T_end.push_back(runs[k].T.back());
      cpu += runs[k].seconds;
    }
    const auto fit = compare::fit_power_law(runs[0].t, mean_T(runs, n, n), t_fit, t_end);
    csv << double(n) << cpu << mean(T_end) << standard_error(T_end) / mean(T_end) << fit.exponent
        << jackknife_exponent_error(runs, n, t_fit, t_end) << fit.exponent_error;
    csv.end_row();
  }
}

}  // namespace

void particle_work_precision(const Context& ctx, FailureLog& failures) {
  cost(ctx, failures);
  statistics(ctx, failures);
}

}  // namespace shockgas::studies
