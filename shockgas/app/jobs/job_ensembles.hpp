#pragma once
// The realizations of a plan computed by every process of a job, each on its
// threads: rank 0 deals the work items out to the ranks (deal(), kItems),
// every finished realization is sent to rank 0 as a record, and rank 0 returns
// them all. Nothing is reduced here and no floating-point number is combined on
// the way: rank 0 reduces each ensemble in index order afterwards, with the
// code a single process uses, so that the result is the same bit for bit for
// any number of ranks and threads.
//
// Failures end the whole job, named by rank 0 in one message:
//  * a realization that throws on rank j: "rank j failed in realization k: ...";
//  * a rank that stops (killed; its node lost): when the launcher then sends the
//    others SIGTERM, rank 0 asks every rank still working to answer within
//    kAnswerSeconds and names those that do not, with the realizations they
//    were running; a rank silent for kSilenceSeconds is named the same way
//    (a launcher that lets the others run on);
//  * SIGTERM or SIGINT to every rank (a scheduler's pre-emption): Interrupted,
//    rank 0 having saved the records gathered so far when it keeps checkpoints;
//    then every rank first saves the states of the realizations it runs
//    (checkpointer.hpp: within Checkpointer::kStateGraceSeconds) and says so
//    (kSaved), and rank 0 waits for that before it ends the job.
// Rank 1 names rank 0 if rank 0 falls silent. Rank 0 writes nothing before it
// holds every record, so a failed job leaves no result.
#include <filesystem>
#include <memory>
#include <vector>

#include "shockgas/app/ensemble/ensemble_plan.hpp"
#include "shockgas/app/jobs/job.hpp"

namespace shockgas::app {

class ProgressBar;
class Checkpointer;

// The messages between the ranks (MPI tags). Numbers travel as doubles, an
// item as its ensemble and index.
enum JobTag : int {
  kProgress = 1,     // any rank -> 0 (and 0 -> 1): fraction done, time reached, collisions, items running
  kRecord = 2,       // -> 0: a finished realization (encode())
  kFailed = 3,       // -> 0: 1 if the input was bad (else 0), an item, then the text of the error
  kInterrupted = 4,  // -> 0: a signal (0: an answer to kStop), then the items running
  kStop = 5,         // 0 -> all: the job is ending, answer with kInterrupted
  kDone = 6,         // 0 -> all: every record arrived
  kItems = 7,        // 0 -> each at the start: the items it runs
  kSaved = 8,        // -> 0 after kInterrupted on a checkpoint request: what its states hold (text)
};

// The numbers before the items of a kProgress message.
inline constexpr std::size_t kProgressNumbers = 3;

inline constexpr double kAnswerSeconds = 0.5;  // well inside Open MPI's 1 s from SIGTERM to SIGKILL
inline constexpr double kSilenceSeconds = 30;  // a rank sends a heartbeat every 0.2 s

struct ComputedRecords {
  std::vector<RealizationRecord> records;  // rank 0: every item of the plan, in plan order; else empty
  int ranks = 1;
  std::size_t threads = 1;  // threads of each process
  double wall_seconds = 0;  // computing them; a resumed run's with its interrupted parts' [s]
};

// With job == nullptr: this process alone (a shard without MPI). `threads`: of
// each process. Rethrows a realization's own error when running alone.
// checkpoints (checkpointer.hpp; this process alone, or rank 0 of a job): the
// records it keeps are not run again, and every record passes through it, so
// that it saves them every output.checkpoint_minutes and on a signal; the
// realizations running here save their states through it. On the other ranks
// of a job: their Checkpointer (job_rank), for their realizations' states.
// nullptr for none. states_dir: where realization 0 keeps its
// states apart when it runs in this process, alone or on rank 0
// (realization_pool.hpp); on another rank its record carries them.
ComputedRecords compute_records(Job* job, std::shared_ptr<const EnsemblePlan> plan, std::size_t threads,
                                ProgressBar& progress, Checkpointer* checkpoints = nullptr,
                                const std::filesystem::path& states_dir = {});

}  // namespace shockgas::app
