#pragma once
// Realizations of a plan run on worker threads in the background, while the
// thread that made the pool keeps talking (to the other ranks of a job, to the
// progress bar). Each realization is particles::simulate on its own initial
// bodies, exactly as particles::run_ensemble runs it, so its record does not
// depend on where or beside what it ran.
#include <chrono>
#include <cstddef>
#include <exception>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "shockgas/app/ensemble/ensemble_plan.hpp"

namespace shockgas::app {

class Checkpointer;

class RealizationPool {
 public:
  struct Failure {
    WorkItem item;
    std::exception_ptr error;
    std::string message;  // error's what()
    bool bad_input;       // an InputError (a damaged saved state): exit 2, as for any input
  };

  // Starts `items` of `plan` on `threads` threads (>= 1). abandon_unfinished:
  // the destructor stops the realizations still running at their engine's next
  // progress report (about 0.1 s; the job is ending) instead of waiting for
  // them to finish.
  // states_dir: where realization 0 of an ensemble whose scene keeps_states_apart
  // writes its states as it runs (state_file.hpp; its record then holds none);
  // empty: realization 0's record holds them. checkpoints: the running
  // realizations save their states there and continue from the states it
  // holds (checkpointer.hpp); nullptr for none.
  RealizationPool(std::shared_ptr<const EnsemblePlan> plan, std::vector<WorkItem> items, std::size_t threads,
                  bool abandon_unfinished, std::filesystem::path states_dir = {},
                  Checkpointer* checkpoints = nullptr);
  // Starts no further realization; waits for the running ones (stopped first if abandoned).
  ~RealizationPool();
  RealizationPool(const RealizationPool&) = delete;
  RealizationPool& operator=(const RealizationPool&) = delete;

  // The records finished since the last call (realization 0 whole or with its
  // states apart, the others without states).
  std::vector<RealizationRecord> take_finished();
  // The first realization that failed, if one did (no further one is started).
  std::optional<Failure> failure() const;
  // The realizations running now.
  std::vector<WorkItem> running() const;
  // The fraction of the pool's realizations done (each counting equally) and
  // the largest simulated time reported.
  double fraction() const;
  double sim_time() const;
  // The collisions of the pool's realizations so far, in this process (those
  // resumed from a saved state: since their resumption).
  std::uint64_t events() const;
  // Every item finished, or one failed and the others stopped.
  bool finished() const;
  // Returns once a realization ended (finished or failed) or a worker thread
  // ended since the last call returned (true), or after `at_most` without
  // either (false): a caller's poll that wakes as soon as there is news
  // instead of sleeping a fixed time.
  bool wait(std::chrono::milliseconds at_most);

 private:
  struct State;
  std::shared_ptr<State> state_;
  std::vector<std::thread> threads_;
  bool abandon_;
  std::uint64_t news_seen_ = 0;  // State::news when wait last returned
};

}  // namespace shockgas::app
