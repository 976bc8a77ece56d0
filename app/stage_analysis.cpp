// Stage 1b: what the particles alone show (compare/particle_analysis.hpp), written
// under /particles/analysis and the summary key "analysis".
#include <cmath>
#include <string>

#include "run_state.hpp"
#include "shockgas/compare/particle_analysis.hpp"
#include "shockgas/compare/theory.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::app {

namespace {

using nlohmann::ordered_json;

ordered_json finite_or_null(double x) { return std::isfinite(x) ? ordered_json(x) : ordered_json(nullptr); }

void write_cooling(RunState& state, const compare::CoolingAnalysis& a) {
  state.h5.set_attribute("/particles/analysis", "T_exponent_theory", compare::kStickyCoolingExponent);
  state.h5.set_attribute("/particles/analysis", "T_cooling_exponent_theory", compare::kHomogeneousCoolingExponent);
  auto& s = state.summary["analysis"];
  if (!a.not_determined.empty()) {
    s["cooling_law_not_determined"] = a.not_determined;
    state.report.push_back("- cooling_law: not determined (" + a.not_determined + ").\n");
    return;
  }
  if (!a.fit) return;
  const auto& fit = *a.fit;
  std::vector<double> ft = {fit.t_min, fit.t_max}, fT;
  for (double ti : ft) fT.push_back(fit.prefactor * std::pow(ti, fit.exponent));
  state.h5.write("/particles/analysis/T_fit_t", ft, "time", "window of the late-time power-law fit");
  state.h5.write("/particles/analysis/T_fit_T", fT, "length^2/time^2", "the fitted power law at the window ends");
  state.h5.write("/particles/analysis/T_local_exponent", a.local_exponent, "1", "d ln T / d ln t at /particles/t");
  state.h5.set_attribute("/particles/analysis", "T_exponent", fit.exponent);
  const auto& cross = a.crossovers;
  s["T_exponent"] = fit.exponent;
  s["T_exponent_error"] = fit.exponent_error;
  s["T_fit_window"] = {fit.t_min, fit.t_max};
  s["t_dissip"] = finite_or_null(cross.t_dissip);
  s["t_stick"] = finite_or_null(cross.t_stick);
  s["t_dissip_theory"] = cross.t_dissip_theory;
  s["t_stick_theory"] = cross.t_stick_theory;
  state.report.push_back("## Cooling law\n");
  state.report.push_back("- T ~ t^a with a = " + brief(fit.exponent) + " +- " + brief(fit.exponent_error) + " on [" +
                         brief(fit.t_min) + ", " + brief(fit.t_max) +
                         "] (sticky-gas regime theory: " + compare::kStickyCoolingExponentText + ").");
  state.report.push_back("- Crossovers read off d ln T / d ln t: t_dissip = " + brief(cross.t_dissip) +
                         " (theory ~ 1/eps = " + brief(cross.t_dissip_theory) + "), t_stick = " +
                         brief(cross.t_stick) + " (theory ~ eps^(-3/2) = " + brief(cross.t_stick_theory) +
                         "); nan = the local exponent never reaches the t^-2 regime (none for moderately inelastic "
                         "gases, e.g. r = 0.5) or the crossover is outside the sampled window.\n");
}

void write_distribution(RunState& state, const compare::DistributionAnalysis& a) {
  auto& s = state.summary["analysis"];
  if (a.collapse_distance) {
    s["velocity_collapse_distance"] = *a.collapse_distance;
    state.report.push_back("## Velocity distribution\n");
    state.report.push_back("- Collapse of P(v,t) t^(-1/3) against z = v t^(1/3) over " +
                           std::to_string(a.late.size()) + " times in [" + brief(a.late.front().t) + ", " +
                           brief(a.late.back().t) + "]: mean L1 distance " + brief(*a.collapse_distance) +
                           " (0 = perfect collapse, 2 = disjoint).");
  }
  if (!a.not_determined.empty()) {
    s["velocity_distribution_not_determined"] = a.not_determined;
    state.report.push_back("- velocity_distribution: not determined (" + a.not_determined + ").\n");
    return;
  }
  if (!a.collapse_distance) return;
  s["velocity_tail_zmin"] = a.tail_z_min;
  const std::string theory = "theory: " + brief(compare::kTailExponent);
  if (a.tail.at_bound) {
    s["velocity_tail_exponent"] = nullptr;
    state.report.push_back("- Tail ln Phi ~ -c |z|^a for |z| >= " + brief(a.tail_z_min) +
                           ": not determined (the best a sits at the scan bound: too few or too noisy tail "
                           "points; " + theory + ").\n");
    return;
  }
  s["velocity_tail_exponent"] = a.tail.exponent;
  s["velocity_tail_exponent_error"] = a.tail.exponent_error;
  state.report.push_back("- Tail ln Phi ~ -c |z|^a for |z| >= " + brief(a.tail_z_min) + " (one standard deviation): a = " +
                         brief(a.tail.exponent) + " +- " + brief(a.tail.exponent_error) + " (" + theory + ").\n");
}

}  // namespace

void run_analysis_stage(RunState& state) {
  const auto& scene = state.scene;
  write_cooling(state, compare::analyse_cooling(state.t_series, state.T_series, scene.particles.r,
                                                scene.particles.t_end, scene.compare.fit_window));
  write_distribution(state, compare::analyse_velocity_distribution(state.histogram, scene.compare.distribution_t_min));
}

}  // namespace shockgas::app
