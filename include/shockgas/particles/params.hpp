#pragma once
// Scene table [particles]: the physics of the gas and what to observe.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace shockgas::particles {

struct ParticleParams {
  double r = 0.9;                       // restitution coefficient [1], 0 <= r <= 1; r = 0 merges
  double delta = 1e-2;                  // velocity threshold [length/time], >= 0; 0 = none
  std::string subthreshold = "elastic"; // sub-threshold collisions: "elastic" | "sticky" (merge)
  std::string geometry = "ring";        // "ring" (periodic, length L) | "line" (open)
  std::string solver = "events";        // "events" (event-driven) | "hull" (exact, r = 0 only)
  std::string schedule = "auto";        // event order: "auto" | "windows" | "global" (window_scheduler.hpp)
  double t_end = 1000.0;                // final time [time], > 0
  std::size_t samples = 40;             // number of log-spaced sample times in [1, t_end], >= 1
  std::size_t realizations = 1;         // independent realizations (ensemble), >= 1
  std::size_t threads = 0;              // worker threads for ensembles; 0 = all cores
  std::vector<double> snapshots = {};   // times at which to store x, v, m [time]
  bool spacetime = false;               // record trajectories for a space-time diagram (N <= 10^4)
  std::size_t histogram_bins = 0;       // bins of the scaled velocity histogram z = v t^(1/3); 0 = none
  double histogram_zmax = 4.0;          // histogram range |z| <= zmax [length/time^(2/3)]
  std::size_t spacetime_frames = 200;   // frames of the space-time record, equally spaced in [0, t_end], >= 2
  bool clusters = true;                 // count clusters (find_clusters, default criteria) at the samples
  std::uint64_t max_collisions = 0;     // stop a realization after this many collisions; 0 = no limit
  double max_wall_seconds = 0.0;        // stop a realization after this wall-clock time [s]; 0 = no limit
};

// Throws InputError naming the first key out of range.
void validate(const ParticleParams& p);

}  // namespace shockgas::particles
