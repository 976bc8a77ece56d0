#pragma once
// A run that keeps checkpoints (checkpoint.hpp) while its realizations are
// computed in this process: the records finished so far are saved every
// output.checkpoint_minutes, and when the host asks for a checkpoint (the
// command turns SIGTERM and SIGINT into InterruptMode::checkpoint requests while
// a Checkpointer lives), they are saved, the running realizations are stopped
// and Interrupted is thrown: the host exits with the signal's status, and
// `shockgas run --resume DIR` runs only the realizations not saved.
//
// A realization is saved whole or not at all: the work of the ones running when
// the checkpoint is taken is lost (they start again on resume).
#include <chrono>
#include <filesystem>
#include <vector>

#include "checkpoint.hpp"
#include "ensemble_plan.hpp"
#include "shockgas/core/interrupt.hpp"

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

class Checkpointer {
 public:
  // kept: the records of a checkpoint being resumed (empty for a new run);
  // realizations, variants: a shard's slices as given ("" for a whole run).
  Checkpointer(std::filesystem::path dir, const Scene& scene, const std::string& realizations,
               const std::string& variants, std::vector<RealizationRecord> kept);
  ~Checkpointer();  // signals end the process again (partial_outputs.hpp)
  Checkpointer(const Checkpointer&) = delete;
  Checkpointer& operator=(const Checkpointer&) = delete;

  // The items of `plan` still to run: those without a kept record. InputError
  // (key "--resume") if a kept record is not an item of the plan.
  std::vector<WorkItem> remaining(const EnsemblePlan& plan) const;
  // The records of the resumed checkpoint.
  std::size_t kept() const { return kept_; }
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

 private:
  void save();

  std::filesystem::path dir_;
  Checkpoint checkpoint_;
  std::size_t kept_ = 0;   // records of the resumed checkpoint
  std::size_t saved_ = 0;  // records in the file on disk
  std::chrono::steady_clock::duration interval_;
  std::chrono::steady_clock::time_point last_save_;
};

// Whether a signal now asks for a checkpoint (a Checkpointer lives) rather than
// ending the process: read by the command's signal handler (async-signal-safe).
bool signals_take_checkpoints() noexcept;

}  // namespace shockgas::app
