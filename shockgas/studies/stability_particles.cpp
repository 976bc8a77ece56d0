// Stability of the particle engine against delta -> 0 (stability.hpp):
//  * stability_collapse.csv: with delta = 0 inelastic collapse stops a run.
//    Three particles on a line collapse iff r < 7 - 4 sqrt(3) ~ 0.072; on a ring of
//    N particles collapse needs about N_c = -ln(1-r)/(1-r) particles (McNamara &
//    Young, Phys. Fluids A 4, 496 (1992)), so the scan over N and r records where
//    collapse starts and how the collapse time moves with N;
//  * stability_threshold.csv: T(t) at several delta against a small reference
//    delta (same realizations); the time the two part by more than 20 % against
//    the predicted validity t_valid ~ delta^-3, compared while both runs go on.
#include <algorithm>
#include <cmath>

#include "shockgas/core/initial_condition.hpp"
#include "shockgas/particles/simulate.hpp"
#include "shockgas/studies/sections.hpp"
#include "shockgas/studies/stability.hpp"

namespace shockgas::studies {

using particles::ParticleParams;
using particles::RunStop;
using particles::StopReason;

RunStop three_particle_stop(double r) {
  Bodies b;
  b.x = {0.0, 1.0, 2.5};
  b.v = {1.0, 0.0, -1.0};
  b.m = {1.0, 1.0, 1.0};
  ParticleParams p;
  p.r = r;
  p.delta = 0.0;
  p.geometry = particles::Geometry::line;
  p.t_end = 100.0;
  p.samples = 2;
  p.clusters = false;
  p.max_collisions = 1000000;
  p.max_wall_seconds = 5.0;
  return particles::simulate(b, 10.0, p).stop;
}

RunStop ring_stop(std::size_t N, double r, std::uint64_t seed, double t_end) {
  InitialParams ip;
  ip.N = N;
  ip.seed = seed;
  ParticleParams p;
  p.r = r;
  p.delta = 0.0;
  p.t_end = t_end;
  p.samples = 2;
  p.clusters = false;
  p.threads = 1;
  p.max_collisions = 5000000;
  p.max_wall_seconds = 2.0;
  return particles::simulate(make_initial_bodies(ip), double(N), p).stop;
}

double collapse_particles_predicted(double r) { return -std::log1p(-r) / (1 - r); }

namespace {

void three_particle_rows(CsvWriter& csv, FailureLog& failures) {
  const double r_c = 7 - 4 * std::sqrt(3.0);
  for (double r : {0.01, 0.05, 0.07, 0.075, 0.1, 0.3}) {
    const RunStop s = three_particle_stop(r);
    const bool collapsed = s.reason == StopReason::collapse;
    csv << "three on a line" << 3.0 << r << 1.0 << (collapsed ? 1.0 : 0.0) << (collapsed ? s.time : NAN)
        << 3.0
        << particles::to_string(s.reason) + (r < r_c ? " (predicted: collapse)" : " (predicted: none)");
    csv.end_row();
    if (collapsed)
      failures.add(
          {"collapse", "events, delta = 0", "3 particles on a line, r = " + fmt(r),
           "inelastic collapse at t = " + fmt(s.time) + " (predicted for r < 7 - 4 sqrt 3 = 0.0718)"});
  }
}

void ring_rows(const Context& ctx, CsvWriter& csv, FailureLog& failures) {
  const std::vector<std::size_t> sizes =
      ctx.full ? std::vector<std::size_t>{3, 4, 6, 8, 12, 16, 24, 32, 48, 64, 128, 256, 1024}
               : std::vector<std::size_t>{3, 4, 6, 8, 12, 16, 24, 32, 64, 128, 256};
  const std::size_t seeds = ctx.full ? 10 : 4;
  const double t_end = 1000.0;
  for (double r : {0.1, 0.3, 0.5, 0.7, 0.9}) {
    ctx.log("stability", "collapse scan, r = " + fmt(r));
    bool reported = false;
    for (std::size_t N : sizes) {
      std::vector<double> times;
      for (std::size_t k = 0; k < seeds; ++k) {
        const RunStop s = ring_stop(N, r, 100 + k, t_end);
        if (s.reason == StopReason::collapse) times.push_back(s.time);
      }
      std::sort(times.begin(), times.end());
      const double fraction = double(times.size()) / double(seeds);
      const double median = times.empty() ? NAN : times[times.size() / 2];
      csv << "ring" << double(N) << r << double(seeds) << fraction << median
          << collapse_particles_predicted(r)
          << (times.empty() ? std::string("no collapse up to t = ") + fmt(t_end)
                            : std::to_string(times.size()) + " of " + std::to_string(seeds) + " collapsed");
      csv.end_row();
      if (fraction >= 0.5 && !reported) {
        reported = true;
        failures.add({"collapse", "events, delta = 0, ring", "r = " + fmt(r) + ", N = " + std::to_string(N),
                      "inelastic collapse in " + std::to_string(times.size()) + " of " +
                          std::to_string(seeds) + " realizations, median t = " + fmt(median) +
                          " (smallest N collapsing in half; McNamara-Young N_c = " +
                          fmt(collapse_particles_predicted(r)) + ")"});
      }
    }
  }
}

struct MeanT {
  std::vector<double> t, T;
  double seconds = 0;
  std::string stop = "completed";
};

// Mean T(t) over `R` realizations (same seeds for every delta).
MeanT mean_temperature(std::size_t N, double r, double delta, std::size_t R, double t_end, double max_wall) {
  InitialParams ip;
  ip.N = N;
  ip.seed = 3;
  ParticleParams p;
  p.r = r;
  p.delta = delta;
  p.t_end = t_end;
  p.samples = 25;
  p.clusters = false;
  p.realizations = R;
  p.threads = 2;
  p.max_wall_seconds = max_wall;
  const auto e = particles::run_ensemble(ip, p);
  MeanT m;
  m.seconds = e.wall_seconds;
  for (std::size_t i = 0; i < e.t.size(); ++i) {
    if (e.count[i] < double(R)) break;  // a realization stopped early: compare only where all arrived
    m.t.push_back(e.t[i]);
    m.T.push_back(e.T.mean[i]);
  }
  for (const auto& s : e.stops)
    if (s.reason != StopReason::completed) m.stop = particles::to_string(s.reason) + " at t = " + fmt(s.time);
  return m;
}

void threshold_rows(const Context& ctx, CsvWriter& csv, FailureLog& failures) {
  const std::size_t N = ctx.full ? 20000 : 2000, R = ctx.full ? 8 : 4;
  const double t_end = ctx.full ? 1e5 : 1e4, max_wall = ctx.full ? 600.0 : 20.0;
  const double deviation = 0.2;  // 20 %: well above the difference between two small deltas at early times
  for (double r : {0.5, 0.9}) {
    const double ref_delta =
        3e-3;  // small against every compared delta but 1e-3, which is compared too (5x the cost)
    ctx.log("stability", "threshold independence, r = " + fmt(r) + ", reference delta = " + fmt(ref_delta));
    const MeanT ref = mean_temperature(N, r, ref_delta, R, t_end, max_wall);
    for (double delta : {0.3, 0.1, 0.03, 0.01, 0.001}) {
      ctx.log("stability", "threshold independence, r = " + fmt(r) + ", delta = " + fmt(delta));
      const MeanT m = mean_temperature(N, r, delta, R, t_end, max_wall);
      const std::size_t n = std::min(m.t.size(), ref.t.size());
      double t_dev = NAN, worst = 0;
      for (std::size_t i = 0; i < n; ++i) {
        const double rel = std::abs(m.T[i] / ref.T[i] - 1);
        worst = std::max(worst, rel);
        if (rel > deviation && std::isnan(t_dev)) t_dev = m.t[i];
      }
      const double t_valid = std::pow(delta, -3.0);
      csv << r << delta << ref_delta << t_valid << t_dev << worst << (n > 0 ? ref.t[n - 1] : NAN) << m.seconds
          << m.stop + (ref.stop != "completed" ? "; reference " + ref.stop : std::string());
      csv.end_row();
      if (m.stop != "completed")
        failures.add({"threshold", "events, r = " + fmt(r),
                      "delta = " + fmt(delta) + " (N = " + std::to_string(N) + ")",
                      "run stopped early: " + m.stop + " although delta > 0"});
      if (!std::isnan(t_dev))
        failures.add({"threshold", "events, r = " + fmt(r),
                      "delta = " + fmt(delta) + " (N = " + std::to_string(N) + ")",
                      "T(t) departs from delta = " + fmt(ref_delta) + " by > 20 % at t = " + fmt(t_dev) +
                          " (predicted t_valid ~ delta^-3 = " + fmt(t_valid) + ")"});
    }
  }
}

}  // namespace

void particle_stability(const Context& ctx, FailureLog& failures) {
  CsvWriter collapse(ctx.path("stability_collapse.csv"),
                     {"geometry", "N", "r", "realizations", "collapsed_fraction", "median_collapse_time",
                      "N_c_predicted", "what"});
  ctx.log("stability", "collapse of three particles on a line");
  three_particle_rows(collapse, failures);
  ring_rows(ctx, collapse, failures);
  CsvWriter threshold(ctx.path("stability_threshold.csv"),
                      {"r", "delta", "reference_delta", "t_valid_predicted", "t_departs",
                       "max_rel_difference", "t_compared", "seconds", "stop"});
  threshold_rows(ctx, threshold, failures);
}

}  // namespace shockgas::studies
