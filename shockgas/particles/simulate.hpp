#pragma once
// Running the particle gas: one realization from given bodies, or an ensemble of
// realizations of a scene's initial condition.
//
//   RunResult r = simulate(bodies, L, params);           // one run from given bodies
//   RunResult r = simulate(initial, k, params);          // realization k of an initial condition
//   EnsembleResult e = run_ensemble(initial, params);    // R realizations, averaged
//
// params.solver = ParticleSolver::events: the event-driven engine (exact to rounding: each
// collision happens at its predicted contact time; the next events of the two
// bodies are re-predicted). params.solver = ParticleSolver::hull (r = 0 only): the exact sticky
// solution by the lower convex hull (shockgas/core/sticky_hull.hpp), built at the first stop
// time and advanced from its own clusters, no events simulated; its collisions are
// its merges. params.solver = ParticleSolver::automatic: the one of the two that
// chosen_solver(params) names (params.hpp).
#include "shockgas/core/bodies.hpp"
#include "shockgas/core/initial_condition.hpp"
#include "shockgas/core/progress.hpp"
#include "shockgas/particles/params.hpp"
#include "shockgas/particles/run_result.hpp"
#include "shockgas/particles/run_state.hpp"
#include "shockgas/particles/state_sink.hpp"

namespace shockgas::particles {

// One run from `initial` (sorted by x, masses > 0; ring: x in [0, L)) to
// params.t_end, or until it stops early (see RunStop). L: ring length, or on the
// line the extent used for the mean spacing L / N of the cluster criteria; L = 0
// means N, as initial.L does (ring_length, shockgas/core/initial_condition.hpp).
// progress(fraction, t) is called at most about every 0.1 s of work. Where time
// windows apply, their domains run on params.threads threads (0 = every usable
// core, usable_cores()); the result is the same to the bit for any number.
// With a sink, the snapshots and the final state go to it instead of RunResult.
//
// Interruption (shockgas/core/interrupt.hpp), polled at the engine's check points, inside
// time windows too: InterruptMode::abort throws Interrupted within a few 10^4
// collisions; InterruptMode::checkpoint ends the run at the next safe point,
// with stop.reason = StopReason::interrupted at stop.time (see RunStop).
// Throws InputError for bad params or bodies.
//
// checkpoints (run_state.hpp): saves of the run at its safe points, and a saved
// state to continue from instead of starting from `initial`.
RunResult simulate(const Bodies& initial, double L, const ParticleParams& params,
                   const ProgressCallback& progress = {}, const StateSink* sink = nullptr,
                   const RunCheckpoints& checkpoints = {});

// Realization `realization` of a scene's initial condition, as
// simulate(make_initial_bodies(initial.params(), realization), initial.length(), ...),
// bit for bit, without a whole copy of the bodies: bodies the initial condition
// holds (realization 0, data that do not depend on the realization: a file,
// expressions) are read from initial.bodies(), the others are drawn in chunks
// as the engine (or the hull) loads them.
RunResult simulate(const InitialCondition& initial, std::uint64_t realization, const ParticleParams& params,
                   const ProgressCallback& progress = {}, const StateSink* sink = nullptr,
                   const RunCheckpoints& checkpoints = {});
// The same from the parameters; where the bodies can be drawn in chunks
// (InitialStream::streamable), no whole copy of them is ever held.
RunResult simulate(const InitialParams& initial, std::uint64_t realization, const ParticleParams& params,
                   const ProgressCallback& progress = {}, const StateSink* sink = nullptr,
                   const RunCheckpoints& checkpoints = {});

// Throws InputError when params.schedule = "windows" cannot be honoured for
// these bodies (windows need every collision to keep the velocities in their
// range and no inelastic collapse).
void check_schedule(const Bodies& initial, const ParticleParams& params);
// The same for realization 0 of an initial condition, held or drawn.
void check_schedule(const InitialCondition& initial, const ParticleParams& params);

// Peak memory of one run per body, in bytes: the engine's arrays while it runs,
// or the hull's. Measured as the peak resident memory of `shockgas run` less
// that of a run of 10 bodies, at N = 2e6 on one thread (33 bytes with equal
// masses, 36 at N = 1e7; 48 where bodies can merge or masses differ: masses and
// links; 13.5 for the hull, 17.5-19.8 in bench/hull_bench), rounded up;
// tests/app/test_resources.cpp holds it against real runs.
double bytes_per_body(const ParticleParams& params, bool equal_masses);

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
  // jackknife over realizations needs (shockgas/compare/realization_errors.hpp).
  std::vector<std::vector<double>> T_by_realization;          // at the samples it reached
  std::vector<std::vector<double>> histogram_by_realization;  // empty rows without a histogram
  // Each realization's clusters of two or more particles at its end, in index
  // order (RunResult::final_clusters; nullopt where not recorded).
  std::vector<std::optional<Bodies>> final_clusters;
  RunResult first;             // realization 0 in full (final state, snapshots, space-time)
  std::vector<RunStop> stops;  // how each realization ended
  std::vector<std::uint64_t> collisions_per_realization;
  std::uint64_t total_collisions = 0;
  double wall_seconds = 0;  // wall-clock time of the whole ensemble [s]
};

// params.realizations runs of realization k = 0..R-1 of `initial` (seed
// realization_seed(seed, k)), on params.threads threads (0 = every usable core):
// min(R, threads) realizations at once, the threads left over shared out among
// their windows (split_threads). Combined in index order: bit-identical whatever
// the number of threads. Only realization 0 keeps its final state, snapshots and
// space-time record; the others never hold theirs. L = initial.length().
// progress: the mean fraction over realizations, from one thread at a time. On a
// checkpoint request the running realizations stop at a safe point and those not
// started are not run (their stop: StopReason::interrupted at t = 0).
EnsembleResult run_ensemble(const InitialCondition& initial, const ParticleParams& params,
                            const ProgressCallback& progress = {});
// The ensemble of realizations 0..R-1 from their runs in index order (runs[k]
// is realization k, runs[0] whole; of the others only the series, histogram
// density, final clusters, stop and collisions are read): the one reduction of an ensemble,
// whether its realizations ran on threads, on MPI ranks or in shards, so that
// the result depends on none of these. wall_seconds is left 0.
EnsembleResult reduce_ensemble(std::vector<RunResult> runs);

// The same from the parameters (the initial condition built here).
EnsembleResult run_ensemble(const InitialParams& initial, const ParticleParams& params,
                            const ProgressCallback& progress = {});

// Realization k as run_ensemble runs it, wherever it runs (a thread, an MPI
// rank, a shard): realization 0 whole; the others never hold their final
// state, snapshots or space-time record (their snapshots and final state go to
// a sink that discards them).
RunResult run_realization(const InitialCondition& initial, std::uint64_t k, const ParticleParams& params,
                          const ProgressCallback& progress = {}, const RunCheckpoints& checkpoints = {});

// How `threads` threads serve R realizations: `runs` realizations at once, each
// with `per_run` threads for its windows.
struct ThreadSplit {
  std::size_t runs = 1, per_run = 1;
};
ThreadSplit split_threads(std::size_t threads, std::size_t realizations);

}  // namespace shockgas::particles
