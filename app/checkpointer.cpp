#include "checkpointer.hpp"

#include "fault.hpp"

#include <algorithm>
#include <atomic>

#include "shockgas/core/error.hpp"
#include "shockgas/core/interrupt.hpp"
#include "state_file.hpp"

namespace shockgas::app {

namespace {

using Clock = std::chrono::steady_clock;

std::atomic<bool> g_signals_take_checkpoints{false};
static_assert(std::atomic<bool>::is_always_lock_free, "read in a signal handler");

bool same_item(const RealizationRecord& r, const WorkItem& w) {
  return r.ensemble == w.ensemble && r.index == w.index;
}

}  // namespace

bool signals_take_checkpoints() noexcept {
  return g_signals_take_checkpoints.load(std::memory_order_relaxed);
}

Checkpointer::Checkpointer(std::filesystem::path dir, const Scene& scene, const std::string& realizations,
                           const std::string& variants, std::vector<RealizationRecord> kept)
    : dir_(std::move(dir)),
      checkpoint_(make_checkpoint(scene, realizations, variants, std::move(kept))),
      kept_(checkpoint_.records.size()),
      saved_(kept_),
      interval_(std::chrono::duration_cast<Clock::duration>(
          std::chrono::duration<double>(60.0 * scene.output.checkpoint_minutes))),
      last_save_(Clock::now()) {
  g_signals_take_checkpoints = true;
}

Checkpointer::~Checkpointer() { g_signals_take_checkpoints = false; }

std::vector<WorkItem> Checkpointer::remaining(const EnsemblePlan& plan) const {
  const auto& items = plan.items();
  for (const auto& r : checkpoint_.records)
    if (std::none_of(items.begin(), items.end(), [&](const WorkItem& w) { return same_item(r, w); }))
      throw InputError("--resume", to_text(checkpoint_path(dir_).string()),
                       "a checkpoint of this run's realizations (it holds realization " +
                           std::to_string(r.index) + " of ensemble " + std::to_string(r.ensemble) +
                           ", which the run does not compute)");
  std::vector<WorkItem> out;
  for (const auto& w : items)
    if (std::none_of(checkpoint_.records.begin(), checkpoint_.records.end(),
                     [&](const RealizationRecord& r) { return same_item(r, w); }))
      out.push_back(w);
  return out;
}

void Checkpointer::add(std::vector<RealizationRecord> finished) {
  for (auto& r : finished) checkpoint_.records.push_back(std::move(r));
}

void Checkpointer::poll() {
  const InterruptMode request = interrupt_requested();
  if (request == InterruptMode::none) {
    const bool due = interval_ > Clock::duration::zero() && Clock::now() - last_save_ >= interval_;
    if (due && checkpoint_.records.size() > saved_) save();  // else the file on disk holds them all
    if (due) last_save_ = Clock::now();
    return;
  }
  const int signal = interrupt_signal();
  request_interrupt(InterruptMode::abort, signal);  // the running realizations stop
  if (request != InterruptMode::checkpoint) throw Interrupted(signal);
  save();
  const std::size_t n = checkpoint_.records.size();
  throw CheckpointTaken(signal, "checkpoint written: " + std::to_string(n) +
                                    (n == 1 ? " realization finished is" : " realizations finished are") +
                                    " kept in " + checkpoint_path(dir_).string() +
                                    "; continue with: shockgas run --resume " + dir_.string());
}

std::vector<RealizationRecord> Checkpointer::take_records() { return std::exchange(checkpoint_.records, {}); }

void Checkpointer::save() {
  for (const RealizationRecord& r : checkpoint_.records)  // on the disk before the record that needs them
    if (r.states_apart) sync_state_file(state_file_path(dir_, r.ensemble));
  write_checkpoint(dir_, checkpoint_);
  saved_ = checkpoint_.records.size();
  last_save_ = Clock::now();
  fault_point("checkpoint");
}

}  // namespace shockgas::app
