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
  state.report.push_back("- T ~ t^a with a = " + to_text(fit.exponent) + " +- " + to_text(fit.exponent_error) +
                         " on [" + to_text(fit.t_min) + ", " + to_text(fit.t_max) +
                         "] (sticky-gas regime theory: -2/3).");
  state.report.push_back("- Crossovers read off d ln T / d ln t: t_dissip = " + to_text(cross.t_dissip) +
                         " (theory ~ 1/eps = " + to_text(cross.t_dissip_theory) + "), t_stick = " +
                         to_text(cross.t_stick) + " (theory ~ eps^(-3/2) = " + to_text(cross.t_stick_theory) +
                         "); NaN = not crossed in the sampled window.\n");
}

// Scaled distributions at the late half of the sample times (t >= compare.distribution_t_min).
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
  const auto tail = compare::fit_tail_exponent(late.back(), 1.0);
  s["velocity_tail_exponent"] = tail.exponent;
  s["velocity_tail_exponent_error"] = tail.exponent_error;
  state.report.push_back("## Velocity distribution\n");
  state.report.push_back("- Collapse of P(v,t) t^(-1/3) against z = v t^(1/3) over " + std::to_string(late.size()) +
                         " late times: mean L1 distance " + to_text(s["velocity_collapse_distance"].get<double>()) +
                         " (0 = perfect collapse, 2 = disjoint).");
  state.report.push_back("- Tail ln Phi ~ -c |z|^a for |z| >= 1: a = " + to_text(tail.exponent) + " +- " +
                         to_text(tail.exponent_error) + " (theory: 3).\n");
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
