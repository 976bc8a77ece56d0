// The ranks other than 0 of a job (job_ensembles.hpp): each runs the share
// rank 0 deals it and sends every record as it finishes; on a signal it saves
// its running realizations' states and says so (kSaved).
#include <deque>
#include <iostream>
#include <optional>
#include <thread>

#include "shockgas/app/ensemble/checkpointer.hpp"
#include "shockgas/app/ensemble/realization_pool.hpp"
#include "shockgas/app/jobs/job_ensembles.hpp"
#include "shockgas/app/jobs/job_messages.hpp"
#include "shockgas/core/interrupt.hpp"

namespace shockgas::app {

namespace {

using namespace job_messages;

class Worker {
 public:
  Worker(Job& job, std::shared_ptr<const EnsemblePlan> plan, std::size_t threads, Checkpointer* checkpoints)
      : job_(job), plan_(std::move(plan)), threads_(threads), checkpoints_(checkpoints) {}

  void serve() {
    Clock::time_point beat{};
    bool done = false;
    while (true) {
      send_finished();
      if (interrupt_requested() != InterruptMode::none)
        answer(interrupt_signal());  // before failure(): as on rank 0
      if (auto f = pool_ ? pool_->failure() : std::nullopt) {
        job_.send(0, kFailed, pack_items({f->bad_input ? 1.0 : 0.0}, {f->item}) + f->message);
        wait_to_be_ended();
      }
      while (auto m = job_.receive()) {
        if (m->tag == kItems)
          pool_ = std::make_unique<RealizationPool>(plan_, unpack_items(unpack(m->bytes), 0), threads_, true,
                                                    std::filesystem::path(), checkpoints_);
        if (m->tag == kDone) done = true;
        if (m->tag == kStop) {
          const auto signal = unpack(m->bytes);  // a checkpoint request: save the states first
          if (checkpoints_ && !signal.empty() && interrupt_requested() == InterruptMode::none)
            request_interrupt(InterruptMode::checkpoint, static_cast<int>(signal[0]));
          answer(0);
        }
        if (m->tag == kProgress)
          root_running_ = unpack_items(unpack(m->bytes), kProgressNumbers), root_heard_ = Clock::now();
      }
      if (done) return;
      check_root();
      if (seconds_since(beat) > kBeatSeconds) {
        job_.send(0, kProgress,
                  pack_items({fraction(), pool_ ? pool_->sim_time() : 0.0,
                              pool_ ? static_cast<double>(pool_->events()) : 0.0},
                             running()));
        beat = Clock::now();
      }
      if (pool_)
        pool_->wait(kPoll);
      else
        std::this_thread::sleep_for(kPoll);
    }
  }

 private:
  double fraction() const { return pool_ ? pool_->fraction() : 0.0; }
  std::vector<WorkItem> running() const { return pool_ ? pool_->running() : std::vector<WorkItem>{}; }

  // The finished records to rank 0, in order. A record is sent only as rank 0
  // takes it, so a queue of them can outlast the kAnswerSeconds rank 0 gives
  // an answer to a signal: with stop_on_signal the sending stops at a pending
  // signal, whose answer goes first, and the rest follow (save_states).
  void send_finished(bool stop_on_signal = true) {
    if (!pool_) return;
    for (auto& r : pool_->take_finished()) unsent_.push_back(std::move(r));
    while (!unsent_.empty()) {
      if (stop_on_signal && interrupt_requested() != InterruptMode::none) return;
      const RealizationRecord& r = unsent_.front();
      if (checkpoints_) checkpoints_->finished(r.ensemble, r.index);  // rank 0 removes its state
      job_.send(0, kRecord, encode(r));
      unsent_.pop_front();
    }
  }

  [[noreturn]] void answer(int signal) {
    job_.send(0, kInterrupted, pack_items({static_cast<double>(signal)}, running()));
    if (checkpoints_ && interrupt_requested() == InterruptMode::checkpoint) save_states();
    wait_to_be_ended();
  }

  // On a checkpoint request the running realizations save their states at
  // their next safe point and stop (checkpointer.hpp); then rank 0 is told
  // what the states hold. A realization not at a safe point within
  // kStateGraceSeconds keeps its last periodic state.
  void save_states() {
    const Clock::time_point asked = Clock::now();
    while (pool_ && !pool_->finished() && seconds_since(asked) < Checkpointer::kStateGraceSeconds) {
      send_finished(false);
      while (job_.receive()) {
      }
      std::this_thread::sleep_for(kPoll);
    }
    send_finished(false);
    job_.send(0, kSaved, checkpoints_->states_said());
  }

  // Rank 0 ends the job (MPI_Abort) once it has said why; should it not, the
  // job is ended from here after kSilenceSeconds.
  [[noreturn]] void wait_to_be_ended() {
    const Clock::time_point since = Clock::now();
    while (seconds_since(since) < kSilenceSeconds) {
      while (job_.receive()) {
      }
      std::this_thread::sleep_for(kPoll);
    }
    job_.abort(1);
  }

  // Rank 1 speaks when rank 0 falls silent (rank 0 sends it a heartbeat).
  void check_root() {
    if (job_.rank() != 1 || seconds_since(root_heard_) < kSilenceSeconds) return;
    std::cerr << "shockgas: run failed: rank 0 has not answered for " << static_cast<int>(kSilenceSeconds)
              << " s " << describe(*plan_, root_running_)
              << " (killed, or its node was lost); the job stops, no result is written\n";
    job_.abort(1);
  }

  Job& job_;
  std::shared_ptr<const EnsemblePlan> plan_;
  std::size_t threads_;
  Checkpointer* checkpoints_;              // its realizations' states (job_rank), or nullptr
  std::unique_ptr<RealizationPool> pool_;  // once rank 0 has dealt the items (kItems)
  std::deque<RealizationRecord> unsent_;   // finished, not yet sent to rank 0
  std::vector<WorkItem> root_running_;
  Clock::time_point root_heard_ = Clock::now();
};

}  // namespace

void serve_job_rank(Job& job, std::shared_ptr<const EnsemblePlan> plan, std::size_t threads,
                    Checkpointer* checkpoints) {
  Worker(job, std::move(plan), threads, checkpoints).serve();
}

}  // namespace shockgas::app
