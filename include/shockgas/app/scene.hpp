#pragma once
// A scene: one TOML file with a table per part ([initial], [particles],
// [continuum], [compare], [output]). Which tables are present decides what runs:
// a scene without [particles] runs no particles, without [continuum] no solver.
#include <map>
#include <string>
#include <vector>

#include "shockgas/continuum/params.hpp"
#include "shockgas/core/initial_condition.hpp"
#include "shockgas/particles/params.hpp"

namespace shockgas::app {

// Scene table [compare]: the particle-continuum comparison.
struct CompareParams {
  std::string solver = "hopf_lax";   // the continuum solver compared (one of continuum.solvers)
  std::string deposit = "cic";       // particles -> grid: "ngp" (nearest cell) | "cic" (cloud in cell)
  double distribution_t_min = 10.0;  // scaled velocity distributions compared at sample times >= this [time]
  double match_distance = 0.0;       // max shock-cluster distance for a match [length]; 0 = automatic
  double min_cluster_particles = 0;  // clusters and shocks lighter than this many mean particle
                                     // masses are not counted [1]; 0 = max(2, t^(2/3) / 10)
  double cluster_gap = 0.0;          // max gap inside a cluster [length]; 0 = derived from delta
  double cluster_dv = 0.0;           // max relative velocity inside a cluster [length/time]; 0 = derived
  double fit_window = 10.0;          // late window of the T(t) fit: [t_end / fit_window, t_end], > 1
};

// Scene table [sweep]: run the scene once per variant (each a list of
// overrides, "particles.r=0.5; particles.delta=1e-3"), side by side.
struct SweepParams {
  std::vector<std::string> variants;        // overrides per variant, separated by ';'
  std::vector<std::string> labels;          // one per variant; empty = the overrides
  std::string reference_key;                // summary key compared with reference_values ("compare.T_exponent")
  std::vector<std::string> reference_values;  // the literature's values as text, one per variant
                                              // ("" where it gives none), or empty
  std::string reference_source;             // where they come from
};

// Scene table [output].
struct OutputParams {
  bool plots = true;                 // make PNG plots (needs /usr/bin/python3 with matplotlib, h5py)
  bool fields = true;                // store continuum fields (x, v, rho) in result.h5
};

struct Scene {
  std::string name;                  // scene name ([scene] name, else the file's stem)
  std::string description;           // what the scene shows
  std::string expected_runtime;      // wall time on a 2-core machine, as text
  std::string path;                  // file it came from
  std::string text;                  // the scene text as given (before overrides)
  std::vector<std::string> overrides;  // --set key=value, in order

  InitialParams initial;
  particles::ParticleParams particles;
  continuum::ContinuumParams continuum;
  CompareParams compare;
  OutputParams output;
  SweepParams sweep;

  bool has_sweep = false;
  bool has_particles = false;
  bool has_continuum = false;
  bool has_compare = false;

  // Where each key was set ("scene.toml:12" or "--set particles.r=0.5").
  std::map<std::string, std::string> key_origin;

  // Time at which the continuum is evaluated.
  double continuum_t_end() const { return continuum.t_end > 0 ? continuum.t_end : particles.t_end; }
};

// Reads, overrides and validates a scene; throws InputError (located at
// file:line) on an unknown key, a wrong type or a value out of range. No work
// is done and nothing is written before this returns.
Scene load_scene(const std::string& path, const std::vector<std::string>& overrides = {});

// Parses scene text (path used only in messages).
Scene parse_scene(const std::string& text, const std::string& path,
                  const std::vector<std::string>& overrides = {});

// The variants of a [sweep] scene, each parsed and validated as a scene of its
// own (name "<scene>/<label>"); throws InputError before any work.
std::vector<Scene> expand_sweep(const Scene& scene);

// The complete commented scene with every key, its default, unit and allowed
// range, generated from the same registration the parser uses.
std::string default_scene_text();

// The resolved parameters as TOML (every key, after defaults and overrides).
std::string resolved_scene_text(const Scene& scene);

}  // namespace shockgas::app
