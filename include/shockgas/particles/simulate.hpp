#pragma once
// Running the particle gas: one realization from given bodies, or an ensemble of
// realizations of a scene's initial condition.
//
//   RunResult r = simulate(bodies, L, params);           // one run from given bodies
//   RunResult r = simulate(initial, k, params);          // realization k of a scene's initial condition
//   EnsembleResult e = run_ensemble(initial, params);    // R realizations, averaged
//
// params.solver = "events": the event-driven engine (exact to rounding: each
// collision happens at its predicted contact time; the next events of the two
// bodies are re-predicted). params.solver = "hull" (r = 0 only): the exact sticky
// solution by the lower convex hull (core/sticky_hull.hpp) evaluated at each stop
// time, no events simulated; its collisions are its merges.
#include <functional>

#include "shockgas/core/bodies.hpp"
#include "shockgas/core/initial_condition.hpp"
#include "shockgas/core/progress.hpp"
#include "shockgas/particles/params.hpp"
#include "shockgas/particles/run_result.hpp"

namespace shockgas::particles {

// A state to be written, handed out in chunks instead of as a whole copy:
// sorted by x (ring: x in [0, L)), each body once, as RunResult::final_state
// would hold it. read() may be called more than once.
class StateReader {
 public:
  using Chunk = std::function<void(const double* x, const double* v, const double* m, std::size_t count)>;
  virtual std::size_t size() const = 0;  // bodies
  virtual void read(const Chunk& chunk) const = 0;

 protected:
  ~StateReader() = default;
};

// Where the states that are written go as they are reached, instead of into
// RunResult (whose final_state and snapshots then stay empty): a file writer
// streams them in chunks. Snapshot k is at the k-th of params.snapshots in
// ascending order.
struct StateSink {
  std::function<void(std::size_t k, double t, const StateReader& state)> snapshot;
  std::function<void(double t, const StateReader& state)> final_state;
};

// One run from `initial` (sorted by x, masses > 0; ring: x in [0, L)) to
// params.t_end, or until it stops early (see RunStop). L: ring length, or on the
// line the extent used for the mean spacing L / N of the cluster criteria.
// progress(fraction, t) is called at most about every 0.1 s of work. Where time
// windows apply, their domains run on params.threads threads (0 = every usable
// core, usable_cores()); the result is the same to the bit for any number.
// Throws InputError for bad params or bodies.
RunResult simulate(const Bodies& initial, double L, const ParticleParams& params,
                   const ProgressCallback& progress = {});

// Realization `realization` of a scene's initial condition, as
// simulate(make_initial_bodies(initial, realization), domain_length(initial), ...),
// bit for bit; the engine reads the bodies in chunks where the initial condition
// allows it (InitialStream::streamable), so no whole copy of them is held. With
// a sink, the snapshots and the final state go to it (event solver; the hull
// solver keeps them in RunResult).
RunResult simulate(const InitialParams& initial, std::uint64_t realization, const ParticleParams& params,
                   const ProgressCallback& progress = {}, const StateSink* sink = nullptr);

// Throws InputError when params.schedule = "windows" cannot be honoured for
// these bodies (windows need every collision to keep the velocities in their
// range and no inelastic collapse); the second form without building the bodies
// where they can be streamed.
void check_schedule(const Bodies& initial, const ParticleParams& params);
void check_schedule(const InitialParams& initial, const ParticleParams& params);

// Mean and standard error (sample standard deviation / sqrt(count)) over the
// realizations that reached each sample.
struct SeriesStats {
  std::vector<double> mean;
  std::vector<double> stderr_;  // 0 where count < 2
};

struct EnsembleResult {
  std::vector<double> t;      // sample times [time]
  std::vector<double> count;  // realizations that reached each sample [1]
  SeriesStats T, mean_v, n_bodies, n_clusters, collisions, inelastic, elastic, merges, dissipated;
  std::vector<double> histogram;  // mean of the histogram densities (layout of ScaledHistogram)
  RunResult first;                // realization 0 in full (final state, snapshots, space-time)
  std::vector<RunStop> stops;     // how each realization ended
  std::vector<std::uint64_t> collisions_per_realization;
  std::uint64_t total_collisions = 0;
  double wall_seconds = 0;  // wall-clock time of the whole ensemble [s]
};

// params.realizations runs of make_initial_bodies(initial, k), k = 0..R-1 (seed
// realization_seed(initial.seed, k)), on params.threads threads (0 = every usable
// core): min(R, threads) realizations at once, the threads left over shared out
// among their windows (split_threads). Combined in index order: bit-identical
// whatever the number of threads. Only realization 0 keeps its final state,
// snapshots and space-time record.
// L = domain_length(initial). progress: the mean fraction over realizations, from
// one thread at a time.
EnsembleResult run_ensemble(const InitialParams& initial, const ParticleParams& params,
                            const ProgressCallback& progress = {});

// How `threads` threads serve R realizations: `runs` realizations at once, each
// with `per_run` threads for its windows.
struct ThreadSplit {
  std::size_t runs = 1, per_run = 1;
};
ThreadSplit split_threads(std::size_t threads, std::size_t realizations);

}  // namespace shockgas::particles
