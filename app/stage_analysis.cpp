// Stage 1b: what the particles alone show -- the cooling law T(t) ~ t^a with its
// crossovers, and the collapse and tail of the scaled velocity distribution.
// Summary keys stay under "compare" (compare.T_exponent, ...), as scripts expect.
#include <cmath>
#include <string>

#include "run_state.hpp"
#include "shockgas/compare/cooling_law.hpp"
#include "shockgas/compare/velocity_distribution.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::app {

namespace {

using nlohmann::ordered_json;

void fit_cooling(RunState& state) {
  const auto& t = state.t_series;
  const auto& T = state.T_series;
  const double t_end = state.scene.particles.t_end, t_min = t_end / state.scene.compare.fit_window;
  std::size_t in_window = 0;
  for (double ti : t) in_window += ti >= t_min && ti <= t_end;
  if (in_window < 3) return;
  const auto fit = compare::fit_power_law(t, T, t_min, t_end);
  std::vector<double> ft = {fit.t_min, fit.t_max}, fT;
  for (double ti : ft) fT.push_back(fit.prefactor * std::pow(ti, fit.exponent));
  state.h5.write("/particles/analysis/T_fit_t", ft, "time", "window of the late-time power-law fit");
  state.h5.write("/particles/analysis/T_fit_T", fT, "length^2/time^2", "the fitted power law at the window ends");
  state.h5.write("/particles/analysis/T_local_exponent", compare::local_exponents(t, T), "1", "d ln T / d ln t at /particles/t");
  state.h5.set_attribute("/particles/analysis", "T_exponent", fit.exponent);
  const auto cross = compare::find_crossovers(t, T, state.scene.particles.r);
  auto& s = state.summary["compare"];
  s["T_exponent"] = fit.exponent;
  s["T_exponent_error"] = fit.exponent_error;
  s["T_fit_window"] = {fit.t_min, fit.t_max};
  s["t_dissip"] = std::isfinite(cross.t_dissip) ? ordered_json(cross.t_dissip) : ordered_json(nullptr);
  s["t_stick"] = std::isfinite(cross.t_stick) ? ordered_json(cross.t_stick) : ordered_json(nullptr);
  s["t_dissip_theory"] = cross.t_dissip_theory;
  s["t_stick_theory"] = cross.t_stick_theory;
  state.report.push_back("## Cooling law\n");
  state.report.push_back("- T ~ t^a with a = " + brief(fit.exponent) + " +- " + brief(fit.exponent_error) +
                         " on [" + brief(fit.t_min) + ", " + brief(fit.t_max) +
                         "] (sticky-gas regime theory: -2/3).");
  state.report.push_back("- Crossovers read off d ln T / d ln t: t_dissip = " + brief(cross.t_dissip) +
                         " (theory ~ 1/eps = " + brief(cross.t_dissip_theory) + "), t_stick = " +
                         brief(cross.t_stick) + " (theory ~ eps^(-3/2) = " + brief(cross.t_stick_theory) +
                         "); nan = the local exponent never reaches the t^-2 regime (none for moderately inelastic gases, e.g. r = 0.5) or the crossover is outside the sampled window.\n");
}

// Scaled distributions at the late half of the sample times (t >= compare.distribution_t_min).
// Standard deviation of z under a scaled density (bins piecewise constant).
double standard_deviation(const compare::ScaledDistribution& d) {
  double w = 0, m1 = 0, m2 = 0;
  for (std::size_t b = 0; b + 1 < d.z_edges.size(); ++b) {
    const double z = 0.5 * (d.z_edges[b] + d.z_edges[b + 1]), p = d.density[b] * (d.z_edges[b + 1] - d.z_edges[b]);
    w += p;
    m1 += p * z;
    m2 += p * z * z;
  }
  return w > 0 ? std::sqrt(std::max(0.0, m2 / w - (m1 / w) * (m1 / w))) : 0.0;
}

void measure_distribution(RunState& state) {
  const std::size_t bins = state.hist_z.size();
  if (bins < 4 || state.hist_t.empty()) return;
  const double width = state.hist_z[1] - state.hist_z[0];
  std::vector<double> edges(bins + 1);
  for (std::size_t b = 0; b <= bins; ++b) edges[b] = state.hist_z[0] - 0.5 * width + b * width;
  std::vector<compare::ScaledDistribution> late;
  for (std::size_t k = state.hist_t.size() / 2; k < state.hist_t.size(); ++k) {
    if (state.hist_t[k] < state.scene.compare.distribution_t_min) continue;
    std::vector<double> counts(bins);
    for (std::size_t b = 0; b < bins; ++b) counts[b] = state.hist_density[k * bins + b] * width;
    late.push_back(compare::normalise_z_histogram(edges, counts, state.hist_t[k]));
  }
  if (late.size() < 2) return;
  auto& s = state.summary["compare"];
  s["velocity_collapse_distance"] = compare::collapse_distance(late);
  state.report.push_back("## Velocity distribution\n");
  state.report.push_back("- Collapse of P(v,t) t^(-1/3) against z = v t^(1/3) over " + std::to_string(late.size()) +
                         " times in [" + brief(late.front().t) + ", " + brief(late.back().t) +
                         "]: mean L1 distance " + brief(s["velocity_collapse_distance"].get<double>()) +
                         " (0 = perfect collapse, 2 = disjoint).");
  // The tail is fitted on the mean of the collapsed distributions (steadier than
  // one time), beyond one standard deviation of z.
  const auto mean = compare::mean_distribution(late);
  const double z_min = standard_deviation(mean);
  const auto tail = compare::fit_tail_exponent(mean, z_min);
  s["velocity_tail_zmin"] = z_min;
  if (tail.at_bound) {
    s["velocity_tail_exponent"] = nullptr;
    state.report.push_back("- Tail ln Phi ~ -c |z|^a for |z| >= " + brief(z_min) +
                           ": not determined (the best a sits at the scan bound: too few or too noisy tail "
                           "points; theory: 3).\n");
    return;
  }
  s["velocity_tail_exponent"] = tail.exponent;
  s["velocity_tail_exponent_error"] = tail.exponent_error;
  state.report.push_back("- Tail ln Phi ~ -c |z|^a for |z| >= " + brief(z_min) + " (one standard deviation): a = " +
                         brief(tail.exponent) + " +- " + brief(tail.exponent_error) + " (theory: 3).\n");
}

// An analysis that cannot be done on this run's data (too few samples in the
// window, an empty tail) is reported as not determined; the run goes on.
template <class F>
void attempt(RunState& state, const char* what, F&& analysis) {
  try {
    analysis(state);
  } catch (const InputError& e) {
    state.summary["compare"][std::string(what) + "_not_determined"] = e.what();
    state.report.push_back(std::string("- ") + what + ": not determined (" + e.what() + ").\n");
  }
}

}  // namespace

void run_analysis_stage(RunState& state) {
  attempt(state, "cooling_law", fit_cooling);
  attempt(state, "velocity_distribution", measure_distribution);
}

}  // namespace shockgas::app
