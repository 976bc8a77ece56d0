#pragma once
// A run that keeps checkpoints (checkpoint.hpp) while its realizations are
// computed in this process: the records finished so far are saved every
// output.checkpoint_minutes, and when the host asks for a checkpoint (the
// command turns SIGTERM and SIGINT into InterruptMode::checkpoint requests while
// a Checkpointer lives), they are saved, the running realizations are stopped
// and Interrupted is thrown: the host exits with the signal's status, and
// `shockgas run --resume DIR` runs only the realizations not saved.
//
// A realization still running keeps its own state (run_state_file.hpp) beside
// the checkpoint: saved at a safe point of its run (shockgas/particles/run_state.hpp)
// every output.checkpoint_minutes, and on a checkpoint request, where it then
// stops; a resumed run continues it from there. A signal waits for the running
// realizations to save (a write under way is always finished) for at most
// kStateGraceSeconds to reach a safe point; one that does not is stopped, and
// continues from its last periodic state, or starts again if it has none.
//
// In an MPI job every rank saves the states of the realizations it runs into
// the shared directory, each through a Checkpointer of its own: rank 0's keeps
// checkpoint.bin (written before any rank runs, so that every state has one to
// be resumed through) and removes the states of the realizations it saves
// finished; the others' (job_rank) only save states. A resumed run, on any
// number of ranks, continues each realization from its state wherever it runs.
#include <chrono>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <vector>

#include "shockgas/app/ensemble/ensemble_plan.hpp"
#include "shockgas/app/records/checkpoint.hpp"
#include "shockgas/app/records/run_state_file.hpp"
#include "shockgas/core/interrupt.hpp"
#include "shockgas/particles/run_state.hpp"

namespace shockgas::app {

// Interrupted, a checkpoint having been saved: note() says what it keeps and
// how to continue, for the one message the run ends with.
class CheckpointTaken : public Interrupted {
 public:
  CheckpointTaken(int signal_number, std::string note) : Interrupted(signal_number), note_(std::move(note)) {}
  const std::string& note() const { return note_; }

 private:
  std::string note_;
};

class Checkpointer;

// The saves of one running realization into its state file, and the state it
// continues from if the checkpoint holds one; made by Checkpointer::saves_for
// for the realization's run, on the thread that runs it.
class RealizationSaves : public particles::RunSaves {
 public:
  RealizationSaves(Checkpointer& owner, const WorkItem& item);
  ~RealizationSaves() override;
  RealizationSaves(const RealizationSaves&) = delete;
  RealizationSaves& operator=(const RealizationSaves&) = delete;

  // Due every output.checkpoint_minutes of this realization's run (never for 0).
  bool due() override;
  void save(double t, double fraction, const std::function<void(particles::RunStateWriter&)>& write) override;
  // For particles::run_realization: these saves, and the saved state opened
  // (InputError "--resume" if it is damaged).
  particles::RunCheckpoints checkpoints();
  // Where the saved state it continues from was: share of the work done and
  // time, for the progress bar while the state is read.
  std::optional<std::pair<double, double>> resumed_at() const;
  // A realization whose states go to a states file (state_file.hpp): sink()
  // syncs it and says where it stands, for each save; resumed_sink() is what
  // it said at the save resumed, if any.
  void attach_sink(std::function<std::string()> sink) { sink_ = std::move(sink); }
  std::optional<std::string> resumed_sink() const;

 private:
  Checkpointer& owner_;
  WorkItem item_;
  std::chrono::steady_clock::time_point last_;
  std::unique_ptr<particles::RunStateReader> resume_;
  std::function<std::string()> sink_;
};

class Checkpointer {
 public:
  // How long a checkpoint request waits for the running realizations to reach
  // a safe point and save (a scheduler's grace before SIGKILL is usually 30 s).
  static constexpr double kStateGraceSeconds = 20;

  // kept: the records of a checkpoint being resumed and the seconds spent on
  // them (empty for a new run);
  // realizations, variants: a shard's slices as given ("" for a whole run).
  // states: the realizations running in this process save their states;
  // then, resuming, the states in dir are continued (InputError "--resume" for
  // one of another build or scene, or damaged: each is checked whole here,
  // before any realization continues), and for a new run any there are removed.
  // job_rank: a rank other than 0 of a job, which only saves the states of its
  // realizations (rank 0 has checked and cleared the directory before dealing
  // them out): never writes checkpoint.bin nor removes a file, and continues a
  // realization from its state when the directory holds one.
  // work: the run's work directory (run_directory.hpp), where realization 0's
  // states files are written until a checkpoint refers to them: each save
  // moves them into dir. Nothing of a new run goes into dir before its first
  // save, which replaces an earlier run's checkpoint there.
  Checkpointer(std::filesystem::path dir, const Scene& scene, const std::string& realizations,
               const std::string& variants, KeptWork kept, bool resuming = false, bool states = false,
               bool job_rank = false, std::filesystem::path work = {});
  ~Checkpointer();  // signals end the process again
  Checkpointer(const Checkpointer&) = delete;
  Checkpointer& operator=(const Checkpointer&) = delete;

  // The items of `plan` still to run: those without a kept record. InputError
  // (key "--resume") if a kept record is not an item of the plan.
  std::vector<WorkItem> remaining(const EnsemblePlan& plan) const;
  // The records of the resumed checkpoint.
  std::size_t kept() const { return kept_; }
  // Where the checkpoint is kept.
  const std::filesystem::path& dir() const { return dir_; }
  // Wall-clock seconds the run's interrupted parts spent computing up to the
  // checkpoint resumed (0 for a new run) [s].
  double seconds_before() const { return seconds_before_; }
  // Records just finished.
  void add(std::vector<RealizationRecord> finished);
  // Between polls of the computation: saves when the interval has passed and a
  // realization finished since the last save; on a pending interrupt request
  // saves and throws CheckpointTaken (a checkpoint request) or throws
  // Interrupted (an abort), having turned the request into an abort so that the
  // running realizations stop.
  void poll();
  // Every record, kept and new (the checkpoint is left on disk until the result is written).
  std::vector<RealizationRecord> take_records();
  // The saves of realization `item` for its run.
  std::unique_ptr<RealizationSaves> saves_for(const WorkItem& item) {
    return std::make_unique<RealizationSaves>(*this, item);
  }
  // Writes checkpoint.bin if none is on disk yet (rank 0 of a job, before it
  // deals the realizations out: the ranks' states are resumed through it).
  void write_if_missing();
  // A checkpoint request is seen: the grace of the running realizations'
  // saves starts now (else at the first poll() that sees it).
  void request_seen();
  // Saves the records gathered now, if any is not on disk yet (rank 0 of a
  // job on a checkpoint request, before it waits for the ranks' states).
  void save_gathered();
  // The particles are done: a checkpoint on disk (the run was long enough to
  // save one, or resumed one; a job's, always) is brought up to every record,
  // so that an interruption while the results are written keeps them all. A
  // short run, which never saved, does not pay for the write.
  void save_at_end();
  // A realization finished (its record sent to rank 0, which removes its state).
  void finished(std::uint64_t ensemble, std::uint64_t index);
  // What the states of this process hold after a checkpoint request, as in
  // CheckpointTaken's note: "; realization 3 saved at t = 12.5" ...
  std::string states_said() const;
  // What the other ranks of a job said their states hold, for the note of the
  // checkpoint request (rank 0).
  void add_others_said(const std::string& text);
  // What the resumed checkpoint continues: "" or ", 1 continues from its saved state (... at t = 12.5)".
  std::string resumed_states() const;

 private:
  friend class RealizationSaves;
  using Key = std::pair<std::uint64_t, std::uint64_t>;  // ensemble, index
  void find_states();
  void find_state(const Key& key);  // job_rank, resuming: the state of one realization
  bool sink_whole(const RunStateHeader& h) const;
  void save();
  void save_locked(bool fault = true);  // fault: pass fault_point("checkpoint")
  bool waiting_for_states();
  std::string states_note() const;

  std::filesystem::path dir_, work_;
  Checkpoint checkpoint_;
  RunStateHeader identity_;  // version, commit and scene of the state files
  std::size_t kept_ = 0;     // records of the resumed checkpoint
  std::size_t saved_ = 0;    // records in the file on disk
  bool on_disk_ = false;     // checkpoint.bin written (or resumed)
  bool job_rank_ = false;    // saves states only
  bool resuming_ = false;
  std::chrono::steady_clock::duration interval_;
  std::chrono::steady_clock::time_point last_save_;
  std::chrono::steady_clock::time_point started_;  // when this process began computing
  double seconds_before_;                          // spent by the run's earlier parts [s]

  mutable std::mutex mutex_;      // guards what follows and the records (the runs save from their threads)
  std::map<Key, double> states_;  // the realizations with a state on disk: its time
  bool states_checked_ = false;   // their checksums checked (find_states): not read again to resume
  std::map<Key, std::pair<double, double>> resumed_;  // the states the resumed run continues: fraction, t
  std::map<Key, std::string> resumed_sinks_;          // and their states files' saves
  std::set<Key> running_;                             // realizations whose saves live
  std::set<Key> saved_on_request_;
  std::string others_said_;                                     // add_others_said
  int writing_ = 0;                                             // state writes under way
  std::optional<std::chrono::steady_clock::time_point> asked_;  // when a checkpoint request was first seen
};

// Whether a signal now asks for a checkpoint (a Checkpointer lives) rather than
// ending the process: read by the command's signal handler (async-signal-safe).
bool signals_take_checkpoints() noexcept;

}  // namespace shockgas::app
