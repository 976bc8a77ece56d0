#pragma once
// Scene table [particles]: the physics of the gas, how it is solved and what to observe.
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "shockgas/core/parameters.hpp"
#include "shockgas/particles/collision.hpp"

namespace shockgas::particles {

// What a sub-threshold collision does (shockgas/particles/collision.hpp).
enum class Subthreshold { elastic, sticky };
constexpr std::array<EnumName<Subthreshold>, 2> enum_names(Subthreshold) {
  return {{{Subthreshold::elastic, "elastic"}, {Subthreshold::sticky, "sticky"}}};
}

// particles.restitution_law of the constant particles.r, the default
// (restitution_laws.hpp registers it).
inline constexpr char kConstantRestitution[] = "constant";

enum class Geometry { ring, line };
constexpr std::array<EnumName<Geometry>, 2> enum_names(Geometry) {
  return {{{Geometry::ring, "ring"}, {Geometry::line, "line"}}};
}

// How the gas is solved: events = the event-driven engine; hull = the exact
// sticky solution by the lower convex hull (r = 0 only); automatic = whichever
// of the two applies (chosen_solver). simulate.hpp.
enum class ParticleSolver { events, hull, automatic };
constexpr std::array<EnumName<ParticleSolver>, 3> enum_names(ParticleSolver) {
  return {{{ParticleSolver::events, "events"},
           {ParticleSolver::hull, "hull"},
           {ParticleSolver::automatic, "auto"}}};
}

// Event order of the engine (shockgas/particles/window_scheduler.hpp): automatic = time
// windows where they apply, else the global queue.
enum class Schedule { automatic, windows, global };
constexpr std::array<EnumName<Schedule>, 3> enum_names(Schedule) {
  return {{{Schedule::automatic, "auto"}, {Schedule::windows, "windows"}, {Schedule::global, "global"}}};
}

// Whether each realization records its clusters of at least two particles at
// its end (RunResult::final_clusters, for `shockgas stats`): always, never, or
// (auto) when the realization is small enough and they cannot take more than
// kRecordedClustersBytes together (final_clusters_auto_rule()).
enum class ClusterRecord { automatic, always, never };
constexpr std::array<EnumName<ClusterRecord>, 3> enum_names(ClusterRecord) {
  return {{{ClusterRecord::automatic, "auto"},
           {ClusterRecord::always, "always"},
           {ClusterRecord::never, "never"}}};
}
// A gas of N particles holds at most N / 2 clusters of two or more, 24 bytes
// each (x, v, m): 12 bytes per particle and realization in the worst case (a
// young gas of pairs; a late one holds a few hundred: about 1.9 N t^(-2/3) for
// white noise). auto records them when that bound, over every realization, is
// at most 1 GB (N x realizations <= 8.3 x 10^7), and when one realization has
// at most 10^6 particles (kRecordedClustersAutoBodies: its clusters are then at
// most 12 MB, 1.1 x 10^5 of them at N = 10^6 to t = 10, found and written in
// about 0.1 s; above it they are the file's bulk: at N = 10^7 to t = 10,
// 1.1 x 10^6 clusters took about 0.9 s of a 2.9 s command,
// docs/performance/command.md).
inline constexpr double kRecordedClusterBytesPerParticle = 12;
inline constexpr double kRecordedClustersBytes = 1e9;
inline constexpr std::size_t kRecordedClustersAutoBodies = 1000000;
// auto's bound on N x realizations (8.3 x 10^7).
inline constexpr double kRecordedClustersAutoParticles =
    kRecordedClustersBytes / kRecordedClusterBytesPerParticle;
// The words for auto's rule, for the key's description, the layout and messages.
std::string final_clusters_auto_rule();

// Collisions between two safe points of the global queue, where the limits
// (max_collisions, max_wall_seconds), the saves and inelastic collapse are
// looked at (event_engine.hpp).
inline constexpr std::uint64_t kGlobalQueueCheckEvery = 1u << 14;

// Unit, allowed range and meaning of every member: parameters() (shockgas/particles/params.cpp).
struct ParticleParams {
  double r = 0.9;       // 0 = aggregation (every collision merges)
  double delta = 1e-2;  // 0 = no threshold
  Subthreshold subthreshold = Subthreshold::elastic;
  std::string restitution_law = kConstantRestitution;  // a registered law's name
  Geometry geometry = Geometry::ring;
  ParticleSolver solver = ParticleSolver::events;
  Schedule schedule = Schedule::automatic;
  double t_end = 1000.0;
  std::size_t samples = 40;  // log-spaced in [1, t_end]
  std::size_t realizations = 1;
  std::size_t threads = 0;  // 0 = all cores
  std::vector<double> snapshots = {};
  bool spacetime = false;
  std::size_t histogram_bins = 0;  // 0 = no histogram
  double histogram_zmax = 4.0;
  std::size_t spacetime_frames = 200;
  std::size_t spacetime_particles = 2000;  // world lines recorded (run_result.hpp: spacetime_labels)
  bool clusters = true;
  std::size_t min_cluster_particles = 2;  // what the sample-time count counts (MultiParticleRule)
  ClusterRecord final_clusters = ClusterRecord::automatic;
  std::uint64_t max_collisions = 0;  // 0 = no limit (checked at safe points: kGlobalQueueCheckEvery)
  double max_wall_seconds = 0.0;     // 0 = no limit
};

// The declarations of [particles]: key, unit, allowed values, doc.
const ParameterTable<ParticleParams>& parameters();

// Throws InputError naming the first key out of range: the declared rules, then
// the rules between keys (hull only with r = 0 and without the engine's limits, snapshots
// within t_end).
void validate(const ParticleParams& p);

// The solver that runs: for automatic, the hull where it is exact and allowed
// (r = 0: every collision merges; no engine limit, max_collisions or
// max_wall_seconds, set), else the event engine; any other solver as it is.
ParticleSolver chosen_solver(const ParticleParams& p);
// What chosen_solver chose for automatic and why, one line for the user
// ("particles.solver = \"auto\": the event engine, as particles.r = 0.5 > 0");
// "" for any other solver.
std::string solver_choice_note(const ParticleParams& p);

// Whether the realizations of n particles record their final clusters (ClusterRecord).
bool records_final_clusters(const ParticleParams& p, std::size_t n);
// The bound of their bytes over every realization (kRecordedClusterBytesPerParticle).
double final_clusters_bound(const ParticleParams& p, std::size_t n);

// The collision rule of these parameters: r, delta, the sub-threshold kind and
// the restitution law.
CollisionRule collision_rule(const ParticleParams& p);

}  // namespace shockgas::particles
