#include "shockgas/app/jobs/job_ensembles.hpp"

#include <algorithm>
#include <chrono>
#include <iostream>
#include <optional>
#include <thread>

#include "shockgas/app/ensemble/checkpointer.hpp"
#include "shockgas/app/ensemble/realization_pool.hpp"
#include "shockgas/app/jobs/job_messages.hpp"
#include "shockgas/app/run/progress_bar.hpp"
#include "shockgas/core/error.hpp"
#include "shockgas/core/interrupt.hpp"

namespace shockgas::app {

namespace {

using namespace job_messages;

// A rank's input that was not allowed, named with the rank and its realization
// by rank 0: exit 2, as the same input gives one process. Its place is the rank
// (so that no scene line is put before the message).
class RankInputError : public InputError {
 public:
  RankInputError(int rank, std::string text)
      : InputError("", "", "", "rank " + std::to_string(rank), Message{std::move(text)}) {}
};

void sort_in_plan_order(std::vector<RealizationRecord>& records) {
  std::sort(records.begin(), records.end(), [](const RealizationRecord& a, const RealizationRecord& b) {
    return a.index != b.index ? a.index < b.index : a.ensemble < b.ensemble;
  });
}

ComputedRecords compute_alone(std::shared_ptr<const EnsemblePlan> plan, std::size_t threads,
                              ProgressBar& progress, Checkpointer* checkpoints,
                              const std::filesystem::path& states_dir) {
  ComputedRecords out;
  out.threads = threads;
  const std::vector<WorkItem> items = checkpoints ? checkpoints->remaining(*plan) : plan->items();
  RealizationPool pool(plan, items, threads, false, states_dir, checkpoints);
  // The share of the whole run done: a resumed run counts the realizations its
  // checkpoint keeps (its percentage went back to 0 and ran over the rest).
  const double total = static_cast<double>(plan->items().size()),
               remaining = static_cast<double>(items.size());
  const auto done = [&] {
    return total > 0 ? (total - remaining + pool.fraction() * remaining) / total : 1.0;
  };
  auto keep_finished = [&] {
    if (!checkpoints) return;
    checkpoints->add(pool.take_finished());
    checkpoints->poll();  // saves when due; on an interrupt request saves and throws
  };
  while (!pool.finished()) {
    progress.update(done(), pool.sim_time(), pool.events());
    keep_finished();
    pool.wait(kPoll);
  }
  keep_finished();
  if (auto failure = pool.failure()) std::rethrow_exception(failure->error);
  progress.update(done(), pool.sim_time(),
                  pool.events());               // the end: 100 %, which the last poll may have missed
  if (checkpoints) checkpoints->save_at_end();  // an interrupt while the results are written keeps them all
  out.records = checkpoints ? checkpoints->take_records() : pool.take_finished();
  sort_in_plan_order(out.records);
  return out;
}

// Rank 0: deals the items still to run out to the ranks, runs its own share on
// its threads and gathers the others' records as they come; with checkpoints,
// every record passes through them (a resumed job runs only what they lack).
class Gatherer {
 public:
  Gatherer(Job& job, std::shared_ptr<const EnsemblePlan> plan, std::size_t threads, ProgressBar& progress,
           Checkpointer* checkpoints, const std::filesystem::path& states_dir)
      : job_(job),
        plan_(*plan),
        progress_(progress),
        checkpoints_(checkpoints),
        peers_(static_cast<std::size_t>(job.size())) {
    const std::vector<WorkItem> remaining = checkpoints ? checkpoints->remaining(*plan) : plan->items();
    expected_ = remaining.size();
    if (checkpoints) checkpoints->write_if_missing();  // before any rank saves a state
    for (int j = 0; j < job.size(); ++j) {
      std::vector<WorkItem> share = deal(remaining, j, job.size());
      peers_[j].items = share.size();
      peers_[j].heard = Clock::now();
      if (j == 0)
        pool_ =
            std::make_unique<RealizationPool>(plan, std::move(share), threads, true, states_dir, checkpoints);
      else
        job.send(j, kItems, pack_items({}, share));
    }
  }

  std::vector<RealizationRecord> gather() {
    Clock::time_point beat = Clock::now();
    while (true) {
      while (auto m = job_.receive()) handle(*m);
      take_own_finished();
      // An interruption first: the engine stops inside a window on it, and the
      // realization it stopped is not a failure of its own.
      if (interrupt_requested() != InterruptMode::none) stop_on_interrupt();
      if (auto f = pool_->failure()) fail(0, f->item, f->message, f->bad_input);
      check_signalled();
      check_silence();
      keep_records();
      if (received() == expected_) break;
      progress_.update(fraction(), pool_->sim_time(), events());
      if (seconds_since(beat) > kBeatSeconds) {
        job_.send(1, kProgress,
                  pack_items({pool_->fraction(), 0.0, 0.0}, pool_->running()));  // for rank 1 to name us
        beat = Clock::now();
      }
      pool_->wait(kPoll);
    }
    for (int j = 1; j < job_.size(); ++j) job_.send(j, kDone, {});
    if (checkpoints_) checkpoints_->save_at_end();  // as compute_alone
    return checkpoints_ ? checkpoints_->take_records() : std::move(records_);
  }

 private:
  struct Peer {
    std::size_t items = 0, received = 0;
    double fraction = 0;
    std::uint64_t events = 0;  // its collisions so far, as it last said
    std::vector<WorkItem> running;
    Clock::time_point heard;
    bool answered = false;
    int signal = 0;                    // the signal it reported
    std::optional<std::string> saved;  // what its states hold, once it said (kSaved)
    bool working() const { return received < items; }
  };

  void take_own_finished() {
    for (auto& r : pool_->take_finished()) records_.push_back(std::move(r)), ++peers_[0].received;
  }

  std::size_t received() const {
    std::size_t n = 0;
    for (const Peer& p : peers_) n += p.received;
    return n;
  }

  // The records gathered go to the checkpoints, which save them when due.
  void keep_records() {
    if (!checkpoints_) return;
    checkpoints_->add(std::exchange(records_, {}));
    checkpoints_->poll();
  }

  void handle(const JobMessage& m) {
    Peer& p = peers_[m.source];
    p.heard = Clock::now();
    if (m.tag == kRecord) {
      records_.push_back(decode(m.bytes));
      ++p.received;
    } else if (m.tag == kProgress) {
      const auto n = unpack(m.bytes);
      p.fraction = n.at(0);
      p.events = static_cast<std::uint64_t>(n.at(2));
      p.running = unpack_items(n, kProgressNumbers);
    } else if (m.tag == kFailed) {
      const std::size_t head = 3 * sizeof(double);  // bad input, the item, then the message
      const std::vector<double> numbers = unpack(m.bytes.substr(0, head));
      fail(m.source, unpack_items(numbers, 1).at(0), m.bytes.substr(head), numbers.at(0) != 0);
    } else if (m.tag == kInterrupted) {
      const auto n = unpack(m.bytes);
      p.answered = true;
      p.running = unpack_items(n, 1);
      p.signal = static_cast<int>(n.at(0));
      if (p.signal != 0 && !signalled_) signalled_ = Clock::now();
    } else if (m.tag == kSaved) {
      p.saved = m.bytes;
    }
  }

  // A rank reported a signal: the whole job's (rank 0 gets it too, at once), or its own.
  void check_signalled() {
    if (!signalled_ || seconds_since(*signalled_) < kAnswerSeconds) return;
    for (int j = 1; j < job_.size(); ++j)
      if (peers_[j].signal != 0)
        throw RunError("rank " + std::to_string(j) + " was stopped by signal " +
                       std::to_string(peers_[j].signal) + " " + describe(plan_, peers_[j].running) +
                       "; the job stops, no result is written");
  }

  // bad_input: the rank's input was not allowed (a damaged saved state), exit 2
  // as in one process; else the run failed, exit 1.
  [[noreturn]] void fail(int rank, const WorkItem& item, const std::string& message, bool bad_input) {
    std::string text = "rank " + std::to_string(rank) + " failed in " + plan_.describe(item) + ": " +
                       message + "; the job stops, no result is written";
    if (bad_input) throw RankInputError(rank, std::move(text));
    throw RunError(text);
  }

  // A signal reached rank 0: every rank still working must answer; those that
  // cannot were killed with their node or by hand, and the launcher is ending
  // the rest. With checkpoints, what was gathered is saved first (poll() saves
  // on the request and throws Interrupted), then a rank that did not answer is named.
  // On a checkpoint request the ranks save their running realizations' states
  // first (kStop carries the signal; each says kSaved), and rank 0 its own
  // (poll() waits for them).
  [[noreturn]] void stop_on_interrupt() {
    const bool saving = checkpoints_ && interrupt_requested() == InterruptMode::checkpoint;
    const std::string stop = saving ? pack({static_cast<double>(interrupt_signal())}) : std::string();
    for (int j = 1; j < job_.size(); ++j) job_.send(j, kStop, stop);
    const Clock::time_point asked = Clock::now();
    while (seconds_since(asked) < kAnswerSeconds && !all_answered()) {
      receive_answers();
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    take_own_finished();
    int silent = 0;
    for (int j = job_.size() - 1; j >= 1; --j)
      if (peers_[j].working() && !peers_[j].answered) silent = j;
    if (checkpoints_) {
      if (saving) {  // the records first: a launcher may end the job before the states are saved
        checkpoints_->request_seen();  // this rank's own saves run meanwhile, in the same grace
        checkpoints_->add(std::exchange(records_, {}));
        checkpoints_->save_gathered();
      }
      while (saving && seconds_since(asked) < Checkpointer::kStateGraceSeconds + 2 * kAnswerSeconds &&
             !all_saved()) {
        receive_answers();
        take_own_finished();
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
      }
      if (saving) checkpoints_->add_others_said(ranks_saved());
      try {
        while (true) {  // poll() throws once this rank's realizations saved their states
          take_own_finished();
          keep_records();
          std::this_thread::sleep_for(std::chrono::milliseconds(10));
        }
      } catch (const CheckpointTaken& c) {
        if (silent) lost(silent, "stopped", "; " + c.note());
        throw;
      }
    }
    if (silent) lost(silent, "stopped");
    throw Interrupted(interrupt_signal());
  }

  void receive_answers() {
    while (auto m = job_.receive())
      if (m->tag == kInterrupted || m->tag == kRecord || m->tag == kSaved) handle(*m);
  }

  bool all_answered() const {
    for (std::size_t j = 1; j < peers_.size(); ++j)
      if (peers_[j].working() && !peers_[j].answered) return false;
    return true;
  }

  // Every rank that answered and still had realizations to run said what its states hold.
  bool all_saved() const {
    for (std::size_t j = 1; j < peers_.size(); ++j)
      if (peers_[j].working() && peers_[j].answered && !peers_[j].saved) return false;
    return true;
  }

  // What the other ranks' states hold, for the checkpoint's message.
  std::string ranks_saved() const {
    std::string text;
    for (std::size_t j = 1; j < peers_.size(); ++j) {
      const Peer& p = peers_[j];
      if (p.saved)
        text += *p.saved;
      else if (p.working() && p.answered)
        text += "; rank " + std::to_string(j) + " did not say within " +
                to_text(Checkpointer::kStateGraceSeconds + 2 * kAnswerSeconds) +
                " s that it saved its realizations' states " + describe(plan_, p.running) +
                " (each continues from its last state, if any)";
    }
    return text;
  }

  void check_silence() {
    for (int j = 1; j < job_.size(); ++j)
      if (peers_[j].working() && seconds_since(peers_[j].heard) > kSilenceSeconds)
        lost(j, "has not answered for " + std::to_string(static_cast<int>(kSilenceSeconds)) + " s");
  }

  [[noreturn]] void lost(int rank, const std::string& what, const std::string& note = "") {
    throw RunError("rank " + std::to_string(rank) + " " + what + " " + describe(plan_, peers_[rank].running) +
                   " (killed, or its node was lost); the job stops, no result is written" + note);
  }

  double fraction() const {
    double done = pool_->fraction() * static_cast<double>(peers_[0].items);
    for (std::size_t j = 1; j < peers_.size(); ++j)
      done += (peers_[j].working() ? peers_[j].fraction : 1.0) * static_cast<double>(peers_[j].items);
    return expected_ == 0 ? 1.0 : done / static_cast<double>(expected_);
  }
  std::uint64_t events() const {
    std::uint64_t n = pool_->events();
    for (std::size_t j = 1; j < peers_.size(); ++j) n += peers_[j].events;
    return n;
  }

  Job& job_;
  const EnsemblePlan& plan_;
  ProgressBar& progress_;
  Checkpointer* checkpoints_;
  std::vector<Peer> peers_;
  std::size_t expected_ = 0;  // records this job computes: the plan's, less those the checkpoint keeps
  std::vector<RealizationRecord> records_;
  std::unique_ptr<RealizationPool> pool_;
  std::optional<Clock::time_point> signalled_;  // when a rank first reported a signal
};

}  // namespace

ComputedRecords compute_records(Job* job, std::shared_ptr<const EnsemblePlan> plan, std::size_t threads,
                                ProgressBar& progress, Checkpointer* checkpoints,
                                const std::filesystem::path& states_dir) {
  const Clock::time_point start = Clock::now();
  // A resumed run counts the time its interrupted parts spent too.
  const double before = checkpoints ? checkpoints->seconds_before() : 0.0;
  if (!job) {
    ComputedRecords out = compute_alone(std::move(plan), threads, progress, checkpoints, states_dir);
    out.wall_seconds = before + seconds_since(start);
    return out;
  }
  ComputedRecords out;
  out.ranks = job->size();
  out.threads = threads;
  if (job->rank() != 0) {
    serve_job_rank(*job, std::move(plan), threads, checkpoints);
    return out;
  }
  out.records = Gatherer(*job, std::move(plan), threads, progress, checkpoints, states_dir).gather();
  sort_in_plan_order(out.records);
  out.wall_seconds = before + seconds_since(start);
  return out;
}

}  // namespace shockgas::app
