#pragma once
// Where each law of theory.hpp holds. One declaration per law: its value, its
// source, its condition on the scene and the rule that picks the window of
// times it is held against the data (theory_scope.cpp). A report or a plot
// states a law's value only where scope() says it holds, and otherwise "no
// theory for this scene" with the reason.
//
// The conditions (BCDR = Ben-Naim, Chen, Doolen & Redner, PRL 83, 4069 (1999);
// Whitham, Linear and Nonlinear Waves, 1974, ch. 2):
// - The cooling laws, the velocity scaling and the shock count N t^(-2/3) are
//   laws of a homogeneous gas: random initial velocities (uniform or gaussian)
//   of at least kGasParticles particles. A wave given by an expression is not one.
// - T ~ t^(-2/3) from a decade after t_stick = eps^(-3/2) (where
//   T = A t^-2 + B t^(-2/3), meeting at t_stick, still has a local exponent
//   steeper by (4/3) x / (1 + x), x = 10^(-4/3): 0.06) to a tenth of N^(3/2),
//   where about ten clusters are left; the fit window is that part of
//   [t_end / fit_window, t_end].
// - t_dissip ~ 1/eps and t_stick ~ eps^(-3/2) need the homogeneous-cooling
//   regime between them to last: t_stick / t_dissip = eps^(-1/2) >= 3 (r >= 7/9).
// - Clusters are shocks (count, masses, positions): the sticky gas (r = 0) with a
//   uniform initial density is the inviscid Burgers limit exactly (E, Rykov &
//   Sinai, CMP 177, 349 (1996)); a gas with r > 0 from 10 t_stick.
// - Ramps of slope 1/t between shocks (BCDR eq. 7): a homogeneous gas from
//   10 t_stick; a smooth wave from 10 t* (a ramp from a rise of slope s has slope
//   s / (1 + s t), so t * slope = 10/11 at 10 t* where the wave rises fastest).
// - Breaking at t* = 1 / max(-v0'): any v0 given pointwise without a jump.
// - Amplitude ~ t^(-1/2), lobe areas kept (N-wave): an isolated pulse, v0 away
//   from its value at x = 0 on at most a quarter of the domain; the decay from
//   10 t* (the lobes are then triangles to 10 %).
// - Amplitude ~ l / (2 t) (periodic sawtooth): a smooth wave filling the domain,
//   from 10 t*.
// - Data with a jump (t* = 0: Riemann problems) obey none of the decay laws.
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace shockgas::compare {

// Particles below this many are a few bodies, not a gas (plots/shockplot/common.py: GAS_PARTICLES).
inline constexpr std::size_t kGasParticles = 100;

// What the laws' conditions read of a scene.
struct SceneShape {
  static constexpr double kNone = std::numeric_limits<double>::quiet_NaN();
  std::size_t N = 0;               // particles (0: none run)
  bool random_velocities = false;  // initial.velocities uniform or gaussian
  bool uniform_density = false;    // equal masses on a lattice, or rho0 constant
  double r = kNone;                // restitution (NaN: no particles)
  double breaking_time = kNone;    // t* of a pointwise v0 (NaN: none; 0: v0 jumps) [time]
  double pulse_fraction = kNone;   // share of the domain where v0 != v0(0) (NaN: no pointwise v0) [1]
  double fit_window = 10;          // compare.fit_window [1]
};

enum class Law {
  sticky_cooling,    // T ~ t^(-2/3)
  crossovers,        // t_dissip ~ 1/eps, t_stick ~ eps^(-3/2)
  velocity_scaling,  // P(v, t) = t^(1/3) Phi(v t^(1/3)), tail exp(-c |z|^3)
  shock_count,       // about N t^(-2/3) shocks
  clusters_are_shocks,
  ramp_slope,      // slope * t = 1 between shocks
  breaking,        // -1 / min v' = t* - t
  n_wave_decay,    // amplitude ~ t^(-1/2)
  sawtooth_decay,  // amplitude ~ t^(-1)
  lobe_areas,      // A+ and A- kept
};

// Whether a law holds for a scene, and where.
struct Scope {
  bool holds = false;
  std::string reason;           // why not; or, where it holds, the rule that chose the window
  double t_min = 0, t_max = 0;  // the window of times it is held against the data [time]
};

struct TheoryDeclaration {
  Law law;
  const char* id;         // the summary key theory.<id> and the report's tag
  const char* statement;  // the law
  const char* value;      // the number the data are held against
  const char* source;     // where it comes from
  const char* condition;  // when it holds, in words
  Scope (*scope)(const SceneShape&, double t_last);
};

// Every law, in the order of the enum.
const std::vector<TheoryDeclaration>& theory_declarations();
const TheoryDeclaration& declaration(Law law);

// The law's scope for a scene whose data end at t_last (the particles' end, the
// comparison's time or the last frame, whichever the law is held against).
Scope scope(Law law, const SceneShape& shape, double t_last);

// The window T(t) ~ t^a is fitted on: the sticky-gas law's where it holds;
// else [t_end / fit_window, t_end], starting no earlier than a decade after
// the scene's last crossover before t_end (a smooth wave's breaking time t*;
// a gas's t_stick, r > 0), so that no fit spans two regimes or the end of the
// one before. holds = false, with the reason, where that decade is past t_end.
Scope cooling_fit_scope(const SceneShape& shape, double t_end);

// A law's value for report.md where it holds: "theory `id` (source): value",
// else "no theory for this scene (reason)".
std::string theory_note(Law law, const SceneShape& shape, double t_last);

}  // namespace shockgas::compare
