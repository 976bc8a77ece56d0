#pragma once
// Running the particle gas: one realization from given bodies, or an ensemble of
// realizations of a scene's initial condition.
//
//   RunResult r = simulate(bodies, L, params);           // one run
//   EnsembleResult e = run_ensemble(initial, params);    // R realizations, averaged
//
// params.solver = ParticleSolver::events: the event-driven engine (exact to rounding: each
// collision happens at its predicted contact time; the next events of the two
// bodies are re-predicted). params.solver = ParticleSolver::hull (r = 0 only): the exact sticky
// solution by the lower convex hull (core/sticky_hull.hpp) evaluated at each stop
// time, no events simulated; its collisions are its merges.
#include "shockgas/core/bodies.hpp"
#include "shockgas/core/initial_condition.hpp"
#include "shockgas/core/progress.hpp"
#include "shockgas/particles/params.hpp"
#include "shockgas/particles/run_result.hpp"

namespace shockgas::particles {

// One run from `initial` (sorted by x, masses > 0; ring: x in [0, L)) to
// params.t_end, or until it stops early (see RunStop). L: ring length, or on the
// line the extent used for the mean spacing L / N of the cluster criteria.
// progress(fraction, t) is called at most about every 0.1 s of work.
// Throws InputError for bad params or bodies, and Interrupted when an abort is
// requested (core/interrupt.hpp: polled every few thousand collisions).
RunResult simulate(const Bodies& initial, double L, const ParticleParams& params,
                   const ProgressCallback& progress = {});

// Throws InputError when params.schedule = "windows" cannot be honoured for
// these bodies (windows need equal masses, no merges and no inelastic collapse).
void check_schedule(const Bodies& initial, const ParticleParams& params);

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
  // Each realization's own T(t) and histogram density, in index order: what a
  // jackknife over realizations needs (compare/realization_errors.hpp).
  std::vector<std::vector<double>> T_by_realization;          // at the samples it reached
  std::vector<std::vector<double>> histogram_by_realization;  // empty rows without a histogram
  RunResult first;                // realization 0 in full (final state, snapshots, space-time)
  std::vector<RunStop> stops;     // how each realization ended
  std::vector<std::uint64_t> collisions_per_realization;
  std::uint64_t total_collisions = 0;
  double wall_seconds = 0;  // wall-clock time of the whole ensemble [s]
};

// params.realizations runs of initial.realization(k), k = 0..R-1 (realization 0:
// initial.bodies(); seed realization_seed(seed, k)), on params.threads threads
// (0 = all cores), combined in index order: bit-identical whatever the number of
// threads. L = initial.length(). progress: the mean fraction over realizations,
// from one thread at a time.
EnsembleResult run_ensemble(const InitialCondition& initial, const ParticleParams& params,
                            const ProgressCallback& progress = {});
// The ensemble of realizations 0..R-1 from their runs in index order (runs[k]
// is realization k, runs[0] whole; of the others only the series, histogram
// density, stop and collisions are read): the one reduction of an ensemble,
// whether its realizations ran on threads, on MPI ranks or in shards, so that
// the result depends on none of these. wall_seconds is left 0.
EnsembleResult reduce_ensemble(std::vector<RunResult> runs);

// The same from the parameters (the initial condition built here).
EnsembleResult run_ensemble(const InitialParams& initial, const ParticleParams& params,
                            const ProgressCallback& progress = {});

}  // namespace shockgas::particles
