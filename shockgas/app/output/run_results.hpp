#pragma once
// What a run of a scene produced, part by part, as typed values. The stages fill
// it in order -- initial condition, particles, continuum, comparison -- each from
// what the earlier ones handed on, and the result file, summary.json and
// report.md are written from it (output_layout.hpp, report.hpp). Nothing is read
// back from disk.
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "shockgas/app/output/frames.hpp"
#include "shockgas/app/output/statistics_files.hpp"
#include "shockgas/app/records/final_cluster.hpp"
#include "shockgas/app/records/realization_record.hpp"
#include "shockgas/app/scene/scene.hpp"
#include "shockgas/compare/field_distance.hpp"
#include "shockgas/compare/particle_analysis.hpp"
#include "shockgas/compare/realization_errors.hpp"
#include "shockgas/compare/snapshot_comparison.hpp"
#include "shockgas/compare/theory_scope.hpp"
#include "shockgas/compare/white_noise_references.hpp"
#include "shockgas/continuum/field.hpp"
#include "shockgas/core/initial_condition.hpp"
#include "shockgas/particles/simulate.hpp"

namespace shockgas::app {

class ProgressBar;
class StoredStates;  // state_file.hpp

// How the realizations were computed (summary keys parallel.*): not physics,
// and not part of what two runs of one scene must agree on.
struct ParallelRun {
  int ranks = 1;            // processes of the MPI job that computed them
  std::size_t threads = 1;  // threads of each process
  std::size_t shards = 0;   // shards merged into this result (shockgas merge); 0 otherwise
};

struct ParticleResults {
  ParallelRun parallel;
  particles::EnsembleResult ensemble;
  // Realization 0's snapshots and final state in its state file, read in
  // chunks (ensemble.first then holds none of them); null when ensemble.first does.
  std::shared_ptr<const StoredStates> states;
  // Realization 0's heaviest cluster at the end, by the comparison's cluster
  // criteria (summary: analysis.heaviest_cluster_*); none without an initial condition.
  std::optional<HeaviestCluster> heaviest;
  std::vector<particles::Snapshot> frames;  // realization 0 at the animation's frame times (frames.hpp)
  compare::ZHistogram histogram;            // the ensemble-mean scaled histogram (empty: bins = 0)
  compare::CoolingAnalysis cooling;
  compare::DistributionAnalysis distribution;
  // The exact inviscid references of a white-noise start on a lattice (else none),
  // and the exact mass-weighted law of z averaged over the histogram's bins.
  std::optional<compare::WhiteNoiseReferences> exact;
  std::vector<double> histogram_exact;
  // With exact and particles.clusters: the exact expected number of shocks the
  // time series counts (heavier than MultiParticleRule's (k - 1/2) M / N) at each
  // sample time (shock_mass_law.hpp).
  std::vector<double> n_clusters_exact;
  std::optional<compare::AnalysisErrors> errors;  // jackknife over realizations (2 or more)
  // The fitted exponent against the exact sticky gas from the same starts
  // (sticky_same_starts.hpp: r > 0, 2 or more realizations, where it is cheap).
  std::optional<compare::PairedExponents> same_starts;
};

struct ContinuumRun {
  continuum::ContinuumResult result;
  std::optional<double> mass_drift;  // sum rho dx at t over its initial value, minus 1 (if rho)
  // L1 distances to the exact solver on the same grid (shockgas/compare/field_distance.hpp):
  // v relative to the exact v's variation about its mean, rho relative to the mass.
  std::optional<compare::L1Distance> l1_v;
  std::optional<compare::L1Distance> l1_rho;  // where both have a density
  std::optional<double> w1_rho;               // compare::mass_distance to the exact density (both)
};

struct Comparison {
  std::string solver;  // compare.solver
  compare::SnapshotComparison snapshot;
  std::string note;  // set if the solver was re-run to the particles' final time
  // The clusters' masses in bins of doubling width (edges 1.5, 2.5, 4.5, 8.5, ...
  // particle masses: a lone particle is not a cluster), and for a white-noise
  // start the exact expected number of shocks in each bin and of mass >= min_mass.
  std::vector<double> mass_edges, mass_count, mass_exact;
  std::optional<double> n_shocks_exact;
};

// A variant of a sweep, reduced to what the side-by-side needs: its summary and
// the series of its plots (not its states).
// Its implicit move is noexcept: clang-tidy 14 cannot see through nlohmann::ordered_json's
// noexcept move to its asserting invariant check.
// NOLINTNEXTLINE(bugprone-exception-escape)
struct VariantResult {
  std::string label, set, directory;
  nlohmann::ordered_json summary;
  std::vector<double> t, T, T_stderr;  // ensemble-mean T(t) (empty if no particles ran)
  compare::ZHistogram histogram;
  std::vector<double> histogram_exact;                // as ParticleResults
  std::optional<double> temperature_amplitude_exact;  // T t^(2/3) of the sticky gas, white noise only
};

// A shard's content (shard_file.hpp): the records of its slice of the run.
struct ShardResults {
  std::string realizations, variants;  // the slices, "A:B" or "all"
  std::vector<std::string> overrides;  // the --set overrides, to parse the scene again
  std::vector<RealizationRecord> records;
  ParallelRun parallel;
  double wall_seconds = 0;
};

struct RunResults {
  const Scene* scene = nullptr;
  const InitialCondition* initial = nullptr;  // none for a sweep
  compare::SceneShape shape;  // what the laws' conditions read of the scene (theory_scopes.hpp)
  std::optional<ParticleResults> particles;
  std::vector<ContinuumRun> continuum;
  std::optional<Comparison> comparison;
  std::optional<Frames> frames;                // when output.animation
  std::optional<StatisticsResult> statistics;  // when [statistics]
  std::vector<VariantResult> variants;         // a sweep's
  std::optional<ShardResults> shard;           // a shard's
};

// A particle ensemble computed elsewhere (gathered from the ranks of an MPI job,
// merged from shards), handed to a run in place of running it here.
struct ComputedEnsemble {
  particles::EnsembleResult ensemble;
  ParallelRun parallel;
  std::shared_ptr<const StoredStates> states;  // as ParticleResults::states
};
// The ensemble of the scene (or sweep variant) a run asks for, in the order it asks.
using EnsembleSource = std::function<ComputedEnsemble(const Scene&)>;

// The stages (stage_*.cpp). Each takes what earlier stages handed on. The
// particles stage runs the ensemble here unless a source gives it.
// shape: scene_shape(scene, initial) (theory_scopes.hpp), computed once per run.
ParticleResults run_particles(const Scene& scene, const InitialCondition& initial,
                              const compare::SceneShape& shape, ProgressBar& progress,
                              const EnsembleSource& source = {});
std::vector<ContinuumRun> run_continuum(const Scene& scene, const InitialCondition& initial,
                                        ProgressBar& progress);
Comparison run_comparison(const Scene& scene, const InitialCondition& initial,
                          const ParticleResults& particles, const std::vector<ContinuumRun>& continuum);
// [statistics]: the shock statistics of the realizations that reached t_end
// (compare::shock_statistics of their final clusters, moved out of the ensemble
// once written); none when no realization did (the report says so).
std::optional<StatisticsResult> run_statistics_stage(const Scene& scene, particles::EnsembleResult& ensemble);

}  // namespace shockgas::app
