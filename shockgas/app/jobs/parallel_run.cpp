// A run on the processes of an MPI job, or of one shard: the plan's
// realizations computed by every rank (job_ensembles.hpp), then written by
// rank 0: a whole run, or the shard's records.
#include "shockgas/app/jobs/parallel_run.hpp"

#include <algorithm>
#include <cstdio>
#include <iostream>

#include "shockgas/app/directory/run_directory.hpp"
#include "shockgas/app/ensemble/checkpointer.hpp"
#include "shockgas/app/ensemble/realization_pool.hpp"
#include "shockgas/app/jobs/job.hpp"
#include "shockgas/app/jobs/job_ensembles.hpp"
#include "shockgas/app/jobs/shard_file.hpp"
#include "shockgas/app/records/checkpoint.hpp"
#include "shockgas/app/records/state_file.hpp"
#include "shockgas/app/run/progress_bar.hpp"
#include "shockgas/core/cores.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::app {

namespace fs = std::filesystem;

namespace {

// A rank with no realization to run is allowed, and said.
void say_idle_ranks(const Job* job, const EnsemblePlan& plan) {
  if (!job || plan.items().size() >= static_cast<std::size_t>(job->size())) return;
  const std::size_t busy = plan.items().size(), last = static_cast<std::size_t>(job->size()) - 1;
  std::cerr << "shockgas: note: " << job->size() << " ranks for " << busy << " realization"
            << (busy == 1 ? "" : "s") << ": "
            << (busy == last ? "rank " + std::to_string(last) + " has"
                             : "ranks " + std::to_string(busy) + " to " + std::to_string(last) + " have")
            << " none to run\n";
}

// The job's wall time shared among the ensembles in proportion to the time
// their realizations took (a sweep's variants run side by side).
std::vector<double> wall_shares(const EnsemblePlan& plan, const std::vector<RealizationRecord>& records,
                                double wall_seconds) {
  std::vector<double> own(plan.ensembles(), 0.0);
  double all = 0;
  for (const auto& r : records) own[r.ensemble] += r.run.wall_seconds, all += r.run.wall_seconds;
  for (double& w : own) w = all > 0 ? wall_seconds * w / all : wall_seconds / static_cast<double>(own.size());
  return own;
}

// The records of a checkpoint being resumed, less those of a realization 0
// whose state file is not whole (a run killed between the two, or a damaged
// file): it runs again, and the run says so.
KeptWork resumable_work(const fs::path& dir) {
  Checkpoint checkpoint = read_checkpoint(dir);
  std::vector<RealizationRecord>& kept = checkpoint.records;
  const auto lost = [&](const RealizationRecord& r) {
    if (!r.states_apart) return false;
    const auto problem = StoredStates::problem(state_file_path(dir, r.ensemble));
    if (problem)
      std::fprintf(stderr, "shockgas: realization 0 of ensemble %llu runs again: %s\n",
                   static_cast<unsigned long long>(r.ensemble), problem->c_str());
    return problem.has_value();
  };
  kept.erase(std::remove_if(kept.begin(), kept.end(), lost), kept.end());
  return {std::move(kept), checkpoint.seconds};
}

}  // namespace

bool runs_in_parallel(const RunOptions& options) {
  return current_job() || !options.realizations.empty() || !options.variants.empty() ||
         keeps_checkpoints(options);
}

bool keeps_checkpoints(const RunOptions& options) { return options.checkpoint || options.resume; }

std::string run_parallel(const Scene& scene, const fs::path& dir, const RunOptions& options,
                         RunDirectory* out) {
  const std::optional<Slice> realizations = parse_optional_slice(options.realizations, "--realizations");
  const std::optional<Slice> variants = parse_optional_slice(options.variants, "--variants");
  const bool shard = realizations || variants;
  const auto plan = std::make_shared<const EnsemblePlan>(scene, realizations, variants);
  Job* job = current_job();
  if (speaks_for_job()) say_idle_ranks(job, *plan);
  const std::size_t threads = resolved_threads(scene.particles.threads);
  // Realization 0's states go to a file in the run's work directory, moved
  // beside the checkpoint when one refers to it (state_file.hpp); a shard's
  // records carry them.
  const fs::path states_dir = shard || !out ? fs::path() : out->work();
  ComputedRecords computed;
  {
    // Rank 0 keeps a job's checkpoint (job_ensembles.hpp); every rank saves
    // the states of the realizations it runs.
    std::unique_ptr<Checkpointer> checkpoints;
    if (keeps_checkpoints(options) && speaks_for_job())
      checkpoints = std::make_unique<Checkpointer>(dir, scene, options.realizations, options.variants,
                                                   options.resume ? resumable_work(dir) : KeptWork{},
                                                   options.resume, true, false, states_dir);
    else if (keeps_checkpoints(options))
      checkpoints = std::make_unique<Checkpointer>(dir, scene, options.realizations, options.variants,
                                                   KeptWork{}, options.resume, true, true);
    if (checkpoints && options.resume && speaks_for_job())
      std::cerr << "shockgas: resuming " << dir.string() << ": " << checkpoints->kept() << " of "
                << plan->items().size() << " realizations kept from the checkpoint"
                << checkpoints->resumed_states() << "\n";
    ProgressBar progress(options.progress && speaks_for_job());
    progress.stage(job ? "particles, " + std::to_string(job->size()) + " ranks" : "particles",
                   plan->items().size());
    computed = compute_records(job, plan, threads, progress, checkpoints.get(), states_dir);
  }
  if (!speaks_for_job()) return dir.string();
  if (shard) {
    write_shard(out->staging(), scene, *plan, std::move(computed));
    out->commit();
    return dir.string();
  }
  const ParallelRun parallel{computed.ranks, computed.threads, 0};
  const std::size_t finished = computed.records.size();
  try {
    return write_from_records(scene, *plan, std::move(computed.records), parallel, computed.wall_seconds,
                              *out, dir, options, scene.has_sweep ? nullptr : &plan->initial(0),
                              {states_dir, dir});
  } catch (const CheckpointTaken&) {
    throw;
  } catch (const Interrupted& e) {  // after the particles: their checkpoint holds every realization
    if (!keeps_checkpoints(options) || !fs::exists(checkpoint_path(dir))) throw;
    throw CheckpointTaken(e.signal_number(), "all " + std::to_string(finished) +
                                                 " realizations are kept in " +
                                                 checkpoint_path(dir).string() + resume_hint(dir));
  }
}

std::string write_from_records(const Scene& scene, const EnsemblePlan& plan,
                               std::vector<RealizationRecord> records, const ParallelRun& parallel,
                               double wall_seconds, RunDirectory& out, const fs::path& dir,
                               const RunOptions& options, const InitialCondition* initial,
                               const std::vector<fs::path>& states_dirs) {
  const std::vector<double> wall = wall_shares(plan, records, wall_seconds);
  std::vector<std::vector<RealizationRecord>> by_ensemble(plan.ensembles());
  for (auto& r : records) by_ensemble.at(r.ensemble).push_back(std::move(r));
  std::size_t next = 0;  // run_sweep asks in variant order, skipping variants without particles
  EnsembleSource source = [&](const Scene& asked) {
    std::size_t e = next;
    while (e < plan.ensembles() && plan.scene(e).name != asked.name) ++e;
    if (e == plan.ensembles()) throw RunError("the ensemble of " + asked.name + " was not computed");
    next = e + 1;
    std::shared_ptr<const StoredStates> states;
    for (const auto& r : by_ensemble[e])
      if (r.states_apart) states = StoredStates::open(find_state_file(states_dirs, e));
    ComputedEnsemble c{reduce_ensemble_records(std::move(by_ensemble[e]), plan.realizations(e)), parallel,
                       std::move(states)};
    c.ensemble.wall_seconds = wall[e];
    return c;
  };
  std::optional<SweepPlan> sweep;
  std::optional<InitialCondition> built;
  if (scene.has_sweep) {
    sweep = plan_sweep(scene);
  } else if (!initial) {
    built.emplace(build_initial(scene));
    preflight(scene, *built);
    initial = &*built;
  }
  return into_run_directory(out, dir, scene, options, [&](const fs::path& staging) {
    if (sweep)
      run_sweep(scene, *sweep, staging, options, source);
    else
      run_single(scene, *initial, staging, options, {}, source);
  });
}

}  // namespace shockgas::app
