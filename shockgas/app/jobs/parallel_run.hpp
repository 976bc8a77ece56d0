#pragma once
// Writing a run whose particle ensembles were computed elsewhere: gathered from
// the ranks of an MPI job (parallel_run.cpp) or merged from shards (merge.cpp).
// Each ensemble is reduced from its records in index order, then the run goes
// on as a single process's would: the continuum, the comparison, the result
// files, the report and the plots, through run_single and run_sweep.
#include <filesystem>
#include <string>
#include <vector>

#include "shockgas/app/ensemble/ensemble_plan.hpp"
#include "shockgas/app/run/run_internal.hpp"

namespace shockgas::app {

// A run on the processes of an MPI job, or of a slice of the realizations (a
// shard). So does a run that keeps checkpoints (checkpointer.hpp): its records
// are saved as they finish.
bool runs_in_parallel(const RunOptions& options);
bool keeps_checkpoints(const RunOptions& options);
// dir: the output directory, where the checkpoints go; out: the run directory
// it writes (run_directory.hpp), made before any work by the process that
// speaks for the job (nullptr on the other ranks).
std::string run_parallel(const Scene& scene, const std::filesystem::path& dir, const RunOptions& options,
                         RunDirectory* out);

// records: of every realization of every ensemble of `plan` (each ensemble
// computed whole), in any order. wall_seconds: how long computing them took.
// Written into out (dir as given, for messages). initial: realization 0 of a
// scene without sweep, if already built. states_dirs: where the records with
// states_apart have their state files (state_file.hpp), the first that holds
// one.
std::string write_from_records(const Scene& scene, const EnsemblePlan& plan,
                               std::vector<RealizationRecord> records, const ParallelRun& parallel,
                               double wall_seconds, RunDirectory& out, const std::filesystem::path& dir,
                               const RunOptions& options, const InitialCondition* initial = nullptr,
                               const std::vector<std::filesystem::path>& states_dirs = {});

}  // namespace shockgas::app
