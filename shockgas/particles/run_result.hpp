#pragma once
// What a particle run observed: time series at the sample times, the final
// state, and the optional records (snapshots, scaled-velocity histogram,
// space-time record). Only what ParticleParams asks for is filled.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "shockgas/core/bodies.hpp"

namespace shockgas::particles {

// Observables at the sample times; every vector has one entry per sample reached
// (fewer than params.samples if the run stopped early, e.g. at collapse).
struct TimeSeries {
  std::vector<double> t;           // sample time [time]
  std::vector<double> T;           // temperature <v^2> - <v>^2, mass weighted [length^2/time^2]
  std::vector<double> mean_v;      // mass-weighted mean velocity (momentum / mass) [length/time]
  std::vector<double> n_bodies;    // live bodies (clusters after merges) [1]
  std::vector<double> n_clusters;  // clusters of >= min_cluster_particles particles (find_clusters,
                                   // default criteria; MultiParticleRule) [1]
  std::vector<double> collisions;  // cumulative collisions, all kinds [1]
  std::vector<double> inelastic;   // cumulative inelastic collisions (g >= delta, r > 0) [1]
  std::vector<double> elastic;     // cumulative sub-threshold elastic collisions [1]
  std::vector<double> merges;      // cumulative merges [1]
  std::vector<double> dissipated;  // cumulative kinetic energy lost [mass length^2/time^2]

  std::size_t size() const { return t.size(); }
  // Visits every column: f(name, vector), name as in the result file.
  template <class F>
  void for_each_column(F&& f) {
    f("t", t), f("T", T), f("mean_v", mean_v), f("n_bodies", n_bodies), f("n_clusters", n_clusters);
    f("collisions", collisions), f("inelastic", inelastic), f("elastic", elastic);
    f("merges", merges), f("dissipated", dissipated);
  }
};

// The state at a requested time (params.snapshots).
struct Snapshot {
  double t = 0;   // [time]
  Bodies bodies;  // sorted by x; ring: x in [0, L)
};

// Mass-weighted histogram of z = (v - <v>) t^(1/3) at each sample time (the
// paper's Fig. 4): density[k * bins + b] is the mass fraction in bin b divided by
// the bin width, so it integrates to the mass fraction with |z| <= zmax.
struct ScaledHistogram {
  double zmax = 0;              // range [-zmax, zmax] [length/time^(2/3)]
  std::size_t bins = 0;         // bins per sample; bin b is centred at -zmax + (b + 1/2) 2 zmax / bins
  std::vector<double> t;        // sample times [time]
  std::vector<double> density;  // row-major, t.size() x bins [time^(2/3)/length]
};

// Space-time record for small N (the paper's Fig. 3): the position of each
// recorded original particle (a merged particle at its cluster's position) at
// equally spaced times in [0, t_end]; the recorded particles are
// spacetime_labels(N, params.spacetime_particles).
struct SpaceTime {
  std::vector<std::size_t> labels;  // the recorded particles' labels (0 .. N-1, initial order), increasing
  std::vector<double> t;            // frame times [time]
  std::vector<double> x;            // row-major, t.size() x labels.size(); ring: in [0, L) [length]
};

// The labels of K = min(n, most) of n particles, evenly spaced:
// floor(k (n - 1) / (K - 1)) for k = 0 .. K-1, so the first (0) and the last
// (n - 1) are always among them; all n when n <= most. n < 2^32 (no overflow).
inline std::vector<std::size_t> spacetime_labels(std::size_t n, std::size_t most) {
  const std::size_t K = n < most ? n : most;
  std::vector<std::size_t> labels(K);
  for (std::size_t k = 0; k < K; ++k) labels[k] = K == 1 ? 0 : k * (n - 1) / (K - 1);
  return labels;
}

// How a run ended.
enum class StopReason : std::uint8_t {
  completed,    // reached t_end
  collapse,     // inelastic collapse (delta = 0, 0 < r < 1): time stopped advancing
  event_limit,  // params.max_collisions reached
  wall_limit,   // params.max_wall_seconds reached
  stall,        // no collapse is possible (delta > 0, or r = 0 or 1), yet time stopped
                // advancing through rounding (2^24 collisions at one time); not physics
  interrupted,  // a checkpoint was requested (shockgas/core/interrupt.hpp): stopped at a safe point
};
std::string to_string(StopReason reason);

// A run stopped by `interrupted` ends at a safe point: a state the uninterrupted
// run passes through as well (the event engine: the end of a time window or
// sub-window, or a check point of the global queue), every record up to
// stop.time kept; run on from there, it gives the uninterrupted run's results.
struct RunStop {
  StopReason reason = StopReason::completed;
  double time = 0;      // simulated time reached [time] (collapse: the collapse time)
  double position = 0;  // collapse or stall: where (ring: in [0, L)); else 0 [length]
};

// How the event engine ordered the collisions (shockgas/particles/window_scheduler.hpp).
struct RunSchedule {
  std::string order = "global";  // "windows", "global", or "windows, then global"
  std::string why_global;        // when not (only) windows: why, and what windows would need
  std::size_t threads = 1;       // threads that ran the windows
};

struct RunResult {
  TimeSeries series;
  Bodies final_state;  // at stop.time: sorted; ring: x in [0, L)
  // At stop.time, when params.final_clusters asks (records_final_clusters): the
  // clusters (find_clusters, gas_cluster_criteria at stop.time; r = 0: the merged
  // bodies) holding at least two particles (MultiParticleRule), the clusters the
  // time series counts, as centre of mass x, velocity v and mass m, in order of
  // x (ring: in [0, L)).
  std::optional<Bodies> final_clusters;
  std::vector<Snapshot> snapshots;  // the requested times reached
  ScaledHistogram histogram;        // empty unless params.histogram_bins > 0
  SpaceTime spacetime;              // empty unless params.spacetime
  RunStop stop;
  // Temperature of the bodies the run started from, TemperatureSums over them
  // in order as they were drawn or read (a resumed run draws them again), as
  // initial_temperature() (initial_stream.hpp); nullopt in a run never started.
  std::optional<double> initial_temperature;
  std::uint64_t collisions = 0;  // total collisions (hull solver: merges)
  double wall_seconds = 0;       // wall-clock time of the run [s]
  RunSchedule schedule;          // event solver only
};

}  // namespace shockgas::particles
