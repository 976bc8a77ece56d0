#pragma once
// A scene: one TOML file with a table per part ([initial], [particles],
// [continuum], [compare], [output]). Which tables are present decides what runs:
// a scene without [particles] runs no particles, without [continuum] no solver.
#include <array>
#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include "shockgas/compare/params.hpp"
#include "shockgas/continuum/params.hpp"
#include "shockgas/core/initial_condition.hpp"
#include "shockgas/particles/params.hpp"

namespace shockgas::app {

// Scene table [sweep]: run the scene once per variant (each a list of
// overrides, "particles.r=0.5; particles.delta=1e-3"), side by side. The keys
// of [scene], [sweep] and [output] are declared in shockgas/app/scene/scene_schema.cpp.
struct SweepParams {
  std::vector<std::string> variants;          // overrides per variant, separated by ';'
  std::vector<std::string> labels;            // one per variant; empty = the overrides
  std::string reference_key;                  // summary key compared with reference_values
  std::vector<std::string> reference_values;  // one per variant ("" where none), or empty
  std::string reference_source;
};

// How the frames of an animation are spaced in time (shockgas/app/output/frames.hpp).
enum class FrameSpacing { linear, log };
constexpr std::array<EnumName<FrameSpacing>, 2> enum_names(FrameSpacing) {
  return {{{FrameSpacing::linear, "linear"}, {FrameSpacing::log, "log"}}};
}

// Whether result.h5 keeps a state of realization 0 (/initial/x, v, m or
// /particles/final/x, v, m): always, never, or (auto) when it has at most
// kStoredStateBodies bodies. The initial state is drawn again from the scene
// and its seed (InitialCondition) whenever it is not kept.
enum class KeepState { automatic, always, never };
constexpr std::array<EnumName<KeepState>, 3> enum_names(KeepState) {
  return {{{KeepState::automatic, "auto"}, {KeepState::always, "always"}, {KeepState::never, "never"}}};
}
// 10^5 bodies: 2.4 MB of float64, about 1.2 MB deflated and 0.03 s of deflate
// (shuffle, level 4, Fletcher32); a state of 10^6 bodies took 0.25 s, as long as
// the whole run of N = 10^6 to t = 10 without it (docs/output.md, "States of
// realization 0").
inline constexpr std::size_t kStoredStateBodies = 100000;
inline bool keeps_state(KeepState k, std::size_t bodies) {
  return k == KeepState::always || (k == KeepState::automatic && bodies <= kStoredStateBodies);
}

// Scene table [output].
struct OutputParams {
  bool plots = true;  // needs /usr/bin/python3 with matplotlib, h5py
  bool fields = true;
  KeepState initial = KeepState::automatic;      // /initial/x, v, m
  KeepState final_state = KeepState::automatic;  // /particles/final/x, v, m
  bool animation = false;  // record frames; animation.mp4 and .gif (shockgas/app/output/frames.hpp)
  std::size_t animation_frames = 60;
  FrameSpacing animation_spacing = FrameSpacing::linear;
  double animation_t_min = 0;  // first frame after t = 0 of log spacing; 0 = t_end / 1000
  double checkpoint_minutes =
      10;  // save finished realizations this often (shockgas/app/records/checkpoint.hpp); 0 = on signals only
};

struct Scene {
  std::string name;                    // scene name ([scene] name, else the file's stem)
  std::string description;             // what the scene shows
  std::string expected_runtime;        // wall time on a 2-core machine, as text
  std::string path;                    // file it came from
  std::string text;                    // the scene text as given (before overrides)
  std::vector<std::string> overrides;  // --set key=value, in order
  // What particles.solver = "auto" chose, and why (particles::solver_choice_note);
  // "" for another solver. particles.solver holds the choice.
  std::string solver_note;

  InitialParams initial;
  particles::ParticleParams particles;
  continuum::ContinuumParams continuum;
  compare::CompareParams compare;
  OutputParams output;
  SweepParams sweep;

  bool has_sweep = false;
  bool has_particles = false;
  bool has_continuum = false;
  bool has_compare = false;
  bool has_statistics = false;  // [statistics]: the shock statistics into the run directory

  // Where each key was set ("scene.toml:12" or "--set particles.r=0.5").
  std::map<std::string, std::string> key_origin;

  // Time at which the continuum is evaluated.
  double continuum_t_end() const { return continuum.t_end > 0 ? continuum.t_end : particles.t_end; }
};

// The complete commented scene with every key, its default, unit and allowed
// range, generated from the same declarations the parser uses.
std::string default_scene_text();

// docs/scenes.md: every table and key with kind, default, unit, allowed values
// and meaning, generated from the declarations (a test keeps the file equal to it).
std::string scene_reference_markdown();

// The resolved parameters as TOML (every key, after defaults and overrides).
std::string resolved_scene_text(const Scene& scene);

// The resolved parameters (resolved_scene_text) that decide the results: all
// but the thread count and the checkpoint interval.
std::string physics_of(const std::string& resolved);
// The scene's name in resolved parameters ([scene] name); "" where the text
// is not TOML or names none.
std::string scene_name_of(const std::string& resolved);
// The first line in which two texts differ, "`a` against `b`"; "" if none.
std::string first_difference(const std::string& a, const std::string& b);

}  // namespace shockgas::app
