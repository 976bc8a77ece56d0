#include "shockgas/compare/theory_scope.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "shockgas/compare/theory.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::compare {

namespace {

constexpr double kDecade = 10;        // a law is held from a decade after its crossover [1]
constexpr double kPulseShare = 0.25;  // an isolated pulse covers at most this share of the domain [1]
constexpr double kSeparated = 3;      // t_stick / t_dissip of separated regimes [1]

std::string text(double x) { return to_text(x, 3); }

Scope fails(std::string reason) { return {false, std::move(reason), 0, 0}; }

// Holds on [t_min, t_max] if that window is not empty.
Scope window(double t_min, double t_max, const std::string& rule) {
  if (!(t_min < t_max))
    return fails(rule + " leaves no time before t = " + text(t_max) + " (it would start at " + text(t_min) +
                 ")");
  return {true, rule, t_min, t_max};
}

bool has_particles(const SceneShape& s) { return std::isfinite(s.r); }

// The laws of a homogeneous gas: an empty reason where they can hold.
std::string not_a_gas(const SceneShape& s) {
  if (!has_particles(s)) return "no particles";
  if (!s.random_velocities) return "not a gas with random initial velocities";
  if (s.N < kGasParticles) return std::to_string(s.N) + " particles are not a gas";
  return "";
}

double sticky_start(const SceneShape& s) { return kDecade * sticking_time(s.r); }

bool smooth_wave(const SceneShape& s) { return std::isfinite(s.breaking_time) && s.breaking_time > 0; }

std::string not_a_smooth_wave(const SceneShape& s) {
  if (std::isnan(s.breaking_time)) return "no initial velocity given pointwise";
  if (s.breaking_time == 0) return "v0 jumps (a shock from t = 0): no smooth wave to decay";
  if (!std::isfinite(s.breaking_time)) return "v0 never decreases: no shock forms";
  return "";
}

Scope sticky_cooling(const SceneShape& s, double t_last) {
  if (const auto why = not_a_gas(s); !why.empty()) return fails(why);
  const double one_cluster = std::pow(static_cast<double>(s.N), 1.5) / kDecade;
  return window(std::max(t_last / s.fit_window, sticky_start(s)), std::min(t_last, one_cluster),
                "[max(t_end / fit_window, 10 t_stick), min(t_end, N^(3/2) / 10)]");
}

Scope crossovers(const SceneShape& s, double t_last) {
  if (const auto why = not_a_gas(s); !why.empty()) return fails(why);
  if (!(sticking_time(s.r) >= kSeparated * dissipation_time(s.r)))
    return fails("r = " + text(s.r) +
                 ": t_stick / t_dissip = eps^(-1/2) < 3, no homogeneous-cooling regime between them");
  return {true, "0 < eps <= 1/9", 0, t_last};
}

Scope in_the_sticky_regime(const SceneShape& s, double t_last) {
  if (const auto why = not_a_gas(s); !why.empty()) return fails(why);
  return window(sticky_start(s), t_last, "from 10 t_stick");
}

Scope clusters_are_shocks(const SceneShape& s, double t_last) {
  if (has_particles(s) && s.r == 0 && s.uniform_density) return {true, "r = 0, uniform density", 0, t_last};
  if (has_particles(s) && s.r == 0)
    return fails("a non-uniform density: a delta-shock is not Burgers' shock");
  return in_the_sticky_regime(s, t_last);
}

Scope ramp_slope(const SceneShape& s, double t_last) {
  if (smooth_wave(s)) return window(kDecade * s.breaking_time, t_last, "from 10 t*");
  return in_the_sticky_regime(s, t_last);
}

// The crossovers of a T(t) curve of this scene, by name: a wave's breaking
// time t*; a gas's t_dissip and t_stick (the last one before t_end counts:
// t_dissip where t_stick comes later).
std::vector<std::pair<std::string, double>> crossovers_of(const SceneShape& s) {
  std::vector<std::pair<std::string, double>> out;
  if (smooth_wave(s)) out.emplace_back("the breaking time t*", s.breaking_time);
  if (not_a_gas(s).empty() && s.r > 0) {
    out.emplace_back("t_dissip ~ 1/eps", dissipation_time(s.r));
    out.emplace_back("t_stick ~ eps^(-3/2)", sticking_time(s.r));
  }
  return out;
}

Scope breaking(const SceneShape& s, double t_last) {
  if (const auto why = not_a_smooth_wave(s); !why.empty()) return fails(why);
  return {true, "before the first shock", 0, std::min(t_last, s.breaking_time)};
}

bool isolated(const SceneShape& s) { return s.pulse_fraction <= kPulseShare; }

Scope decay(const SceneShape& s, double t_last, bool pulse) {
  if (const auto why = not_a_smooth_wave(s); !why.empty()) return fails(why);
  if (isolated(s) != pulse)
    return fails(pulse ? "v0 fills the domain: not an isolated pulse"
                       : "an isolated pulse: not a periodic wave");
  return window(std::max(t_last / s.fit_window, kDecade * s.breaking_time), t_last,
                "[max(t_end / fit_window, 10 t*), t_end]");
}

Scope n_wave_decay(const SceneShape& s, double t_last) { return decay(s, t_last, true); }
Scope sawtooth_decay(const SceneShape& s, double t_last) { return decay(s, t_last, false); }

Scope lobe_areas(const SceneShape& s, double t_last) {
  if (const auto why = not_a_smooth_wave(s); !why.empty()) return fails(why);
  if (!isolated(s)) return fails("v0 fills the domain: its lobes meet each other's shocks");
  return {true, "an isolated pulse", 0, t_last};
}

}  // namespace

const std::vector<TheoryDeclaration>& theory_declarations() {
  static const std::vector<TheoryDeclaration> all = {
      {Law::sticky_cooling, "sticky_cooling", "T ~ t^a", "a = -2/3", "BCDR eq. 3",
       "random initial velocities, >= 100 particles, t >= 10 t_stick, t <= N^(3/2) / 10", sticky_cooling},
      {Law::crossovers, "crossovers", "crossovers of d ln T / d ln t",
       "t_dissip ~ 1/eps, t_stick ~ eps^(-3/2)", "BCDR eq. 3",
       "random initial velocities, >= 100 particles, r >= 7/9", crossovers},
      {Law::velocity_scaling, "velocity_scaling", "P(v, t) = t^(1/3) Phi(v t^(1/3)), Phi ~ exp(-c |z|^a)",
       "collapse distance 0; a = 3 as |z| -> infinity (about 2 at |z| ~ 2, docs/paper/tail.md)",
       "BCDR eqs. 4, 6", "random initial velocities, >= 100 particles, t >= 10 t_stick",
       in_the_sticky_regime},
      {Law::shock_count, "shock_count", "shocks per ring", "about N t^(-2/3)", "BCDR",
       "random initial velocities, >= 100 particles, t >= 10 t_stick", in_the_sticky_regime},
      {Law::clusters_are_shocks, "clusters_are_shocks", "clusters of the gas = shocks of Burgers", "1",
       "E, Rykov & Sinai 1996; BCDR", "r = 0 with a uniform density, or a gas from 10 t_stick",
       clusters_are_shocks},
      {Law::ramp_slope, "ramp_slope", "v = (x - q) / t between shocks", "slope * t = 1", "BCDR eq. 7",
       "a smooth wave from 10 t*, or a gas from 10 t_stick", ramp_slope},
      {Law::breaking, "breaking", "-1 / min dv/dx = t* - t", "t* = 1 / max(-v0')", "Whitham ch. 2",
       "v0 given pointwise without a jump, before the first shock", breaking},
      {Law::n_wave_decay, "n_wave_decay", "amplitude ~ sqrt(2 A / t)", "exponent -1/2", "Whitham ch. 2",
       "an isolated pulse (<= 1/4 of the domain), t >= 10 t*", n_wave_decay},
      {Law::sawtooth_decay, "sawtooth_decay", "amplitude ~ l / (2 t)", "exponent -1", "Whitham ch. 2",
       "a smooth wave filling the domain, t >= 10 t*", sawtooth_decay},
      {Law::lobe_areas, "lobe_areas", "A+(t) / A+(0) and A-(t) / A-(0)", "1", "Whitham ch. 2",
       "an isolated pulse (<= 1/4 of the domain) without a jump", lobe_areas},
  };
  return all;
}

const TheoryDeclaration& declaration(Law law) {
  return theory_declarations().at(static_cast<std::size_t>(law));
}

Scope scope(Law law, const SceneShape& shape, double t_last) { return declaration(law).scope(shape, t_last); }

Scope cooling_fit_scope(const SceneShape& s, double t_end) {
  if (Scope law = sticky_cooling(s, t_end); law.holds) return law;
  const std::string rule = "[t_end / fit_window, t_end], from a decade after the scene's last crossover";
  double t_min = t_end / s.fit_window;
  for (const auto& [name, t] : crossovers_of(s)) {
    if (!(t < t_end)) continue;
    if (kDecade * t >= t_end)
      return fails("a decade after the crossover " + name + " = " + text(t) + " (" + text(kDecade * t) +
                   ") is past t_end = " + text(t_end) + ": a fit before it would span two regimes");
    t_min = std::max(t_min, kDecade * t);
  }
  return window(t_min, t_end, rule);
}

std::string theory_note(Law law, const SceneShape& shape, double t_last) {
  const TheoryDeclaration& d = declaration(law);
  const Scope s = scope(law, shape, t_last);
  if (!s.holds) return "no theory for this scene (" + std::string(d.id) + ": " + s.reason + ")";
  return "theory `" + std::string(d.id) + "` (" + d.source + "): " + d.value;
}

}  // namespace shockgas::compare
