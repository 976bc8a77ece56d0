#pragma once
// One live run of the lab: a scene's bodies under the engine, advanced frame by
// frame, and what the views draw at the time it reached, each computed by the
// library: the state (LiveRun), its temperature and clusters, the exact sticky
// gas (StickyHull) and the exact Burgers solution of the same initial data
// (solve_hopf_lax). The page asks for frames through lab_api.cpp.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "lab/engine/lab_scenes.hpp"
#include "shockgas/continuum/field.hpp"
#include "shockgas/core/sticky_hull.hpp"
#include "shockgas/particles/cluster_finder.hpp"
#include "shockgas/particles/live_run.hpp"

namespace shockgas::lab {

// The most bodies the lab runs: about 60 bytes each in the engine and the
// frame's copies, and a frame's passes over them stay within a frame's time.
inline constexpr std::size_t kMaxBodies = 100000;

// What the page's controls set. Numbers come as the page's doubles and are
// checked here: N and seed whole, N within kMaxBodies.
struct LabSettings {
  std::string scene = "sine";
  double N = 2000;
  double r = 0;
  double delta = 1e-2;
  bool sticky = false;  // sub-threshold collisions merge (particles.subthreshold)
  bool line = false;    // particles.geometry = "line" (else "ring")
  double seed = 1;
};

// The views' data at one time.
struct LabFrame {
  double t = 0;
  Bodies bodies;                                    // the engine's live bodies, sorted by x
  double T = 0;                                     // temperature <v^2> - <v>^2, mass weighted
  std::vector<particles::Cluster> clusters;         // clusters of two particles' mass or more
  std::vector<StickyCluster> hull;                  // r = 0: the exact sticky gas at t (else empty)
  std::optional<continuum::ContinuumResult> exact;  // Hopf-Lax on `cells` cells (ring only)
};

class LabSession {
 public:
  // Throws InputError naming the key (initial.N, particles.r, ...) for settings
  // the library or the lab does not allow.
  explicit LabSession(const LabSettings& settings);

  // LiveRun::advance: to time t, or to where `budget` collisions stop it.
  particles::LiveRun::Step advance(double t, std::uint64_t budget) { return run_.advance(t, budget); }
  const particles::LiveRun& run() const { return run_; }
  const LabSettings& settings() const { return settings_; }
  std::size_t bodies() const { return initial_.size(); }  // N
  double length() const { return L_; }
  bool ring() const { return !settings_.line; }
  double particle_mass() const { return particle_mass_; }

  // The views at the time reached; the exact field on `cells` cells.
  LabFrame frame(std::size_t cells) const;

 private:
  static particles::ParticleParams params(const LabSettings& s);

  LabSettings settings_;
  const LabScene& scene_;
  Bodies initial_;
  double L_;
  InitialField exact_data_;  // what Hopf-Lax starts from: the scene's v0, rho0, or the bodies
  double particle_mass_;
  particles::LiveRun run_;
};

}  // namespace shockgas::lab
