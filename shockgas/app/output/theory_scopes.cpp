#include "shockgas/app/output/theory_scopes.hpp"

#include <algorithm>
#include <cmath>

#include "shockgas/app/output/frames.hpp"
#include "shockgas/app/output/layout_declarations.hpp"
#include "shockgas/app/output/run_results.hpp"
#include "shockgas/compare/theory.hpp"

namespace shockgas::app {

namespace {

using compare::Law;

constexpr int kProfilePoints = 4096;  // samples of v0 and rho0 for their shape [1]

// Share of [0, length) where v0 differs from v0(0) by more than 1e-9 of its range.
double pulse_fraction(const std::function<double(double)>& v0, double length) {
  std::vector<double> dv(kProfilePoints);
  const double at_origin = v0(0.0);
  for (int i = 0; i < kProfilePoints; ++i) dv[i] = std::abs(v0(length * i / kProfilePoints) - at_origin);
  const double range = *std::max_element(dv.begin(), dv.end());
  const auto away = std::count_if(dv.begin(), dv.end(), [&](double d) { return d > 1e-9 * range; });
  return range > 0 ? static_cast<double>(away) / kProfilePoints : 0.0;
}

bool constant(const std::function<double(double)>& f, double length) {
  const double f0 = f(0.0);
  for (int i = 1; i < kProfilePoints; ++i)
    if (f(length * i / kProfilePoints) != f0) return false;
  return true;
}

bool random_velocities(const InitialParams& p) {
  return p.velocities == Velocities::uniform || p.velocities == Velocities::gaussian;
}

}  // namespace

compare::SceneShape scene_shape(const Scene& scene, const InitialCondition& initial) {
  compare::SceneShape s;
  s.fit_window = scene.compare.fit_window;
  s.random_velocities = random_velocities(scene.initial);
  if (scene.has_particles) {
    s.N = scene.initial.N;
    s.r = scene.particles.r;
  }
  const InitialField& f = initial.field();
  // Random velocities sit on equal masses; the continuum takes those very bodies.
  s.uniform_density = s.random_velocities;
  if (!f.from_bodies()) {
    s.breaking_time = compare::breaking_time(f.v0, f.length);
    s.pulse_fraction = pulse_fraction(f.v0, f.length);
    s.uniform_density = constant(f.rho0, f.length);
  }
  return s;
}

double law_time(const Scene& scene, Law law) {
  switch (law) {
    case Law::sticky_cooling:
    case Law::crossovers:
    case Law::velocity_scaling:
      return scene.particles.t_end;
    case Law::shock_count:
    case Law::clusters_are_shocks:
    case Law::ramp_slope:
      return scene.continuum_t_end();
    case Law::breaking:
    case Law::n_wave_decay:
    case Law::sawtooth_decay:
    case Law::lobe_areas:
      return scene.output.animation ? frame_times(scene).back() : scene.continuum_t_end();
  }
  return scene.continuum_t_end();
}

namespace {

// When the data a law is held against end for this run: law_time, or earlier
// where the particles stopped before particles.t_end (a collapse, a stall, a
// limit): their series end with the last realization's stop, and the
// comparison is made at realization 0's (stage_compare.cpp).
double held_time(const RunResults& r, Law law) {
  const double planned = law_time(*r.scene, law);
  if (!r.particles) return planned;
  const particles::EnsembleResult& e = r.particles->ensemble;
  switch (law) {
    case Law::sticky_cooling:
    case Law::crossovers:
    case Law::velocity_scaling: {
      if (e.stops.empty()) return planned;
      double last = 0;
      for (const particles::RunStop& s : e.stops) last = std::max(last, s.time);
      return std::min(planned, last);
    }
    case Law::shock_count:
    case Law::clusters_are_shocks:
    case Law::ramp_slope:
      return std::min(planned, e.first.stop.time);
    default:
      return planned;
  }
}

}  // namespace

compare::Scope law_scope(const RunResults& r, Law law) {
  return compare::scope(law, r.shape, held_time(r, law));
}

std::string law_note(const RunResults& r, Law law) {
  return compare::theory_note(law, r.shape, held_time(r, law));
}

namespace layout {

std::vector<Declaration> theory_keys() {
  std::vector<Declaration> keys;
  for (const compare::TheoryDeclaration& d : compare::theory_declarations()) {
    const Law law = d.law;
    keys.push_back(key(Part::theory, std::string("theory.") + d.id, "",
                       std::string("whether \"") + d.statement + ": " + d.value + "\" (" + d.source +
                           ") holds for this run (" + d.condition +
                           "; to the time its data end, before t_end where the particles stopped early): "
                           "{holds, window [t_min, t_max] or null, why}",
                       "", [law](const RunResults& r, Emitter& out) {
                         const compare::Scope s = law_scope(r, law);
                         out.json({{"holds", s.holds},
                                   {"window", s.holds ? nlohmann::ordered_json{s.t_min, s.t_max}
                                                      : nlohmann::ordered_json(nullptr)},
                                   {"why", s.reason}});
                       }));
  }
  return keys;
}

}  // namespace layout

}  // namespace shockgas::app
