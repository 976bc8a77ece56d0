#include "shockgas/app/ensemble/realization_pool.hpp"

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <mutex>
#include <thread>
#include <utility>

#include "shockgas/app/ensemble/checkpointer.hpp"
#include "shockgas/app/output/frames.hpp"
#include "shockgas/app/records/state_file.hpp"
#include "shockgas/core/cores.hpp"
#include "shockgas/core/interrupt.hpp"
#include "shockgas/core/thread_start.hpp"
#include "shockgas/particles/simulate.hpp"

namespace shockgas::app {
namespace {
// Thrown from a realization's progress report when its pool is abandoned: the
// engine unwinds from its next check point, as on an abort request.
struct Abandoned {};
}  // namespace

struct RealizationPool::State {
  std::shared_ptr<const EnsemblePlan> plan;
  Checkpointer* checkpoints = nullptr;
  std::vector<WorkItem> items;
  std::size_t threads_per_run = 1;
  std::filesystem::path states_dir;
  std::atomic<std::size_t> next{0};
  std::atomic<bool> stop{false};
  std::atomic<bool> abandoned{false};  // the running realizations stop unfinished
  std::atomic<bool> go{false};         // every worker started (or the pool refused)

  mutable std::mutex mutex;            // guards what follows
  std::vector<double> fraction;        // per item
  std::vector<std::uint64_t> events;   // per item: collisions so far
  std::vector<std::uint64_t> resumed;  // per item: those its saved state held (counted by another process)
  std::vector<bool> active;            // per item
  double sim_time = 0;
  std::size_t ended = 0;  // items finished or failed
  std::size_t workers = 0;
  std::vector<RealizationRecord> finished;
  std::optional<Failure> failure;
  std::uint64_t news = 0;                // counts the realizations and workers ended
  std::condition_variable news_changed;  // notified with each

  void run(std::size_t i) {
    const WorkItem item = items[i];
    const InitialCondition& ic = plan->initial(item.ensemble);
    particles::ParticleParams p = particle_params(plan->scene(item.ensemble));
    p.threads = threads_per_run;
    bool from_save =
        false;  // resumed: its next report (simulate's, on restoring) gives the save's collisions
    auto progress = [this, i, &from_save](double f, double t, std::uint64_t n) {
      if (abandoned) throw Abandoned{};
      std::lock_guard lock(mutex);
      fraction[i] = f;
      if (from_save) resumed[i] = n, from_save = false;  // simulate's report right after restoring
      events[i] = n;
      sim_time = std::max(sim_time, t);
    };
    // Not started on a pending request: a resumed run starts it.
    if (interrupt_requested() != InterruptMode::none) throw Interrupted(interrupt_signal());
    std::unique_ptr<RealizationSaves> saves = checkpoints ? checkpoints->saves_for(item) : nullptr;
    if (const auto at = saves ? saves->resumed_at() : std::nullopt) {
      progress(at->first, at->second, 0);
      from_save = true;
    }
    // Its states file, from where its save left it if resumed (the snapshots
    // taken before the save are there, not in the save).
    std::optional<StateFileWriter> states;
    const Scene& scene = plan->scene(item.ensemble);
    if (item.index == 0 && !states_dir.empty() && keeps_states_apart(scene)) {
      // The final state only where result.h5 keeps it; its heaviest cluster always.
      FinalStateUse use{[keep = scene.output.final_state](std::size_t n) { return keeps_state(keep, n); },
                        [&scene, length = ic.length()](double t, const particles::StateReader& state) {
                          return heaviest_final_cluster(scene, length, t, state);
                        }};
      const std::optional<std::string> resumed = saves ? saves->resumed_sink() : std::nullopt;
      if (resumed)  // beside the checkpoint it was saved with
        states.emplace(state_file_path(checkpoints->dir(), item.ensemble), *resumed, std::move(use));
      else
        states.emplace(state_file_path(states_dir, item.ensemble), std::move(use));
      if (saves)
        saves->attach_sink([&states, dir = checkpoints->dir()] {
          states->move_to(dir);  // a checkpoint refers to it from now on
          return states->saved();
        });
    }
    const particles::RunCheckpoints saved = saves ? saves->checkpoints() : particles::RunCheckpoints{};
    RealizationRecord r{item.ensemble, item.index,
                        states ? particles::simulate(ic, 0, p, progress, &states->sink(), saved)
                               : particles::run_realization(ic, item.index, p, progress, saved),
                        states.has_value()};
    // Stopped at a safe point by a checkpoint request: not finished, so not a
    // record; a resumed run computes it again from its start.
    if (r.run.stop.reason == particles::StopReason::interrupted) throw Interrupted(interrupt_signal());
    if (states) states->commit();  // on the disk before its record is kept
    std::lock_guard lock(mutex);
    fraction[i] = 1;
    events[i] = r.run.collisions;
    sim_time = std::max(sim_time, r.run.stop.time);
    active[i] = false;
    ++ended;
    finished.push_back(std::move(r));
    tell();
  }

  // Under the mutex: wakes RealizationPool::wait.
  void tell() {
    ++news;
    news_changed.notify_all();
  }

  void work() {
    go.wait(false);
    for (std::size_t i = next++; i < items.size() && !stop; i = next++) {
      {
        std::lock_guard lock(mutex);
        active[i] = true;
      }
      try {
        run(i);
      } catch (const Abandoned&) {
        break;  // neither a record nor a failure: nobody waits for either
      } catch (const InputError& e) {
        fail(i, std::current_exception(), e.what(), true);
      } catch (const std::exception& e) {
        fail(i, std::current_exception(), e.what(), false);
      } catch (...) {
        fail(i, std::current_exception(), "unknown error", false);
      }
    }
    std::lock_guard lock(mutex);
    --workers;
    tell();
  }

  void fail(std::size_t i, std::exception_ptr error, std::string message, bool bad_input) {
    stop = true;
    std::lock_guard lock(mutex);
    active[i] = false;
    ++ended;
    if (!failure) failure = Failure{items[i], error, std::move(message), bad_input};
    tell();
  }
};

RealizationPool::RealizationPool(std::shared_ptr<const EnsemblePlan> plan, std::vector<WorkItem> items,
                                 std::size_t threads, bool abandon_unfinished,
                                 std::filesystem::path states_dir, Checkpointer* checkpoints)
    : state_(std::make_shared<State>()), abandon_(abandon_unfinished) {
  State& s = *state_;
  s.plan = std::move(plan);
  s.states_dir = std::move(states_dir);
  s.checkpoints = checkpoints;
  s.items = std::move(items);
  s.fraction.assign(s.items.size(), 0.0);
  s.events.assign(s.items.size(), 0);
  s.resumed.assign(s.items.size(), 0);
  s.active.assign(s.items.size(), false);
  const particles::ThreadSplit split = particles::split_threads(threads, s.items.size());
  s.threads_per_run = split.per_run;  // threads left over go to each run's windows
  const std::size_t workers = s.items.empty() ? 0 : split.runs;
  s.workers = workers;  // counted down by the threads as they end
  // The workers start their realizations once all are started: a thread the
  // system refuses stops the pool before any realization runs.
  try {
    for (std::size_t t = 0; t < workers; ++t)
      threads_.push_back(start_thread([state = state_] { state->work(); }));
  } catch (...) {
    s.stop = true;
    s.go = true;
    s.go.notify_all();
    for (auto& t : threads_) t.join();
    throw;
  }
  s.go = true;
  s.go.notify_all();
}

// Joins always: a thread left running would outlive the objects the process
// destroys at its exit.
RealizationPool::~RealizationPool() {
  state_->stop = true;
  if (abandon_) state_->abandoned = true;
  for (auto& t : threads_) t.join();
}

std::vector<RealizationRecord> RealizationPool::take_finished() {
  std::lock_guard lock(state_->mutex);
  return std::exchange(state_->finished, {});
}

std::optional<RealizationPool::Failure> RealizationPool::failure() const {
  std::lock_guard lock(state_->mutex);
  return state_->failure;
}

std::vector<WorkItem> RealizationPool::running() const {
  std::lock_guard lock(state_->mutex);
  std::vector<WorkItem> out;
  for (std::size_t i = 0; i < state_->items.size(); ++i)
    if (state_->active[i]) out.push_back(state_->items[i]);
  return out;
}

double RealizationPool::fraction() const {
  std::lock_guard lock(state_->mutex);
  if (state_->items.empty()) return 1.0;
  double sum = 0;
  for (double f : state_->fraction) sum += f;
  return sum / static_cast<double>(state_->items.size());
}

std::uint64_t RealizationPool::events() const {
  std::lock_guard lock(state_->mutex);
  std::uint64_t sum = 0;
  for (std::size_t i = 0; i < state_->events.size(); ++i)
    sum += state_->events[i] - std::min(state_->events[i], state_->resumed[i]);
  return sum;
}

double RealizationPool::sim_time() const {
  std::lock_guard lock(state_->mutex);
  return state_->sim_time;
}

bool RealizationPool::finished() const {
  std::lock_guard lock(state_->mutex);
  return state_->workers == 0;
}

bool RealizationPool::wait(std::chrono::milliseconds at_most) {
  std::unique_lock lock(state_->mutex);
  const bool news =
      state_->news_changed.wait_for(lock, at_most, [this] { return state_->news != news_seen_; });
  news_seen_ = state_->news;
  return news;
}

}  // namespace shockgas::app
