#include "shockgas/app/ensemble/checkpointer.hpp"

#include <algorithm>
#include <atomic>
#include <cstdio>

#include "shockgas/app/files/fault.hpp"
#include "shockgas/app/records/state_file.hpp"
#include "shockgas/core/error.hpp"
#include "shockgas/core/interrupt.hpp"

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
                           const std::string& variants, KeptWork kept, bool resuming, bool states,
                           bool job_rank, std::filesystem::path work)
    : dir_(std::move(dir)),
      work_(std::move(work)),
      checkpoint_(make_checkpoint(scene, realizations, variants, std::move(kept.records))),
      kept_(checkpoint_.records.size()),
      saved_(kept_),
      on_disk_(resuming || job_rank),
      job_rank_(job_rank),
      resuming_(resuming),
      interval_(std::chrono::duration_cast<Clock::duration>(
          std::chrono::duration<double>(60.0 * scene.output.checkpoint_minutes))),
      last_save_(Clock::now()),
      started_(last_save_),
      seconds_before_(kept.seconds) {
  identity_.version = checkpoint_.version;
  identity_.commit = checkpoint_.commit;
  identity_.resolved = checkpoint_.resolved;
  if (states && resuming && !job_rank)  // a job's rank 0 has checked and cleared the directory
    find_states();
  g_signals_take_checkpoints = true;
}

// The states beside the resumed checkpoint: of this build and scene, whole
// (each checksum checked before any realization continues: one that did would
// move its states file on, and a refusal after that would leave a checkpoint
// that cannot be resumed), or refused; those of realizations it holds finished
// are stale and removed.
void Checkpointer::find_states() {
  for (const RunStateHeader& h : read_run_state_headers(dir_)) {
    const std::filesystem::path file = run_state_path(dir_, h.ensemble, h.index);
    // The thread count and the checkpoint interval may differ: they change no result.
    const bool same_scene = physics_of(h.resolved) == physics_of(identity_.resolved);
    if (h.version != identity_.version || h.commit != identity_.commit || !same_scene)
      throw InputError("--resume", to_text(file.string()),
                       "a realization's state saved by this build (" + std::string(identity_.version) +
                           ", commit " + identity_.commit + ") of the checkpoint's scene (it was saved by " +
                           h.version + ", commit " + h.commit + (!same_scene ? ", of another scene" : "") +
                           "; it is left as it is)");
    const bool finished = std::any_of(
        checkpoint_.records.begin(), checkpoint_.records.end(),
        [&](const RealizationRecord& r) { return r.ensemble == h.ensemble && r.index == h.index; });
    std::error_code ec;
    if (finished)
      std::filesystem::remove(file, ec);
    else if (!sink_whole(h))
      continue;  // it starts again
    else
      states_[{h.ensemble, h.index}] = h.time, resumed_[{h.ensemble, h.index}] = {h.fraction, h.time},
                           resumed_sinks_[{h.ensemble, h.index}] = h.sink;
  }
  for (const auto& [key, time] : states_) check_run_state(run_state_path(dir_, key.first, key.second));
  states_checked_ = true;
}

// Whether the states file a saved realization 0 goes on writing is as its
// save recorded it (each state it lists checked against its checksums): a
// damaged, cut or missing one would end the resumed run after all its work, so
// that realization starts again instead (as when a finished realization 0's
// states file is not whole), and the run says so.
bool Checkpointer::sink_whole(const RunStateHeader& h) const {
  if (h.sink.empty()) return true;
  const auto problem = StoredStates::saved_problem(states_in_progress_path(dir_, h.ensemble), h.sink);
  if (problem)
    std::fprintf(stderr, "shockgas: realization %llu of ensemble %llu runs again: %s\n",
                 static_cast<unsigned long long>(h.index), static_cast<unsigned long long>(h.ensemble),
                 problem->c_str());
  return !problem;
}

void Checkpointer::find_state(const Key& key) {
  const std::optional<RunStateHeader> h = read_run_state_header(run_state_path(dir_, key.first, key.second));
  if (!h) return;
  states_[key] = h->time, resumed_[key] = {h->fraction, h->time}, resumed_sinks_[key] = h->sink;
}

void Checkpointer::write_if_missing() {
  std::lock_guard lock(mutex_);
  if (!on_disk_) save_locked(false);
}

void Checkpointer::save_gathered() {
  std::lock_guard lock(mutex_);
  if (checkpoint_.records.size() > saved_) save_locked(false);
}

void Checkpointer::save_at_end() {
  std::lock_guard lock(mutex_);
  if (on_disk_ && checkpoint_.records.size() > saved_) save_locked(false);
}

void Checkpointer::finished(std::uint64_t ensemble, std::uint64_t index) {
  std::lock_guard lock(mutex_);
  states_.erase({ensemble, index});
}

std::string Checkpointer::states_said() const {
  std::lock_guard lock(mutex_);
  return states_note();
}

void Checkpointer::add_others_said(const std::string& text) {
  std::lock_guard lock(mutex_);
  others_said_ += text;
}

std::string Checkpointer::resumed_states() const {
  std::lock_guard lock(mutex_);
  if (resumed_.empty()) return "";
  std::string text = ", " + std::to_string(resumed_.size()) +
                     (resumed_.size() == 1 ? " continues" : " continue") + " from a saved state (";
  std::size_t shown = 0;
  for (const auto& [key, at] : resumed_) {
    const double t = at.second;
    if (shown++ == 3) {
      text += ", ...";
      break;
    }
    text += (shown > 1 ? ", " : "") + std::string("realization ") + std::to_string(key.second) +
            " at t = " + to_text(t, 6);
  }
  return text + ")";
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
  std::lock_guard lock(mutex_);
  for (auto& r : finished) checkpoint_.records.push_back(std::move(r));
}

void Checkpointer::poll() {
  const InterruptMode request = interrupt_requested();
  if (request == InterruptMode::none) {
    const bool due = interval_ > Clock::duration::zero() && Clock::now() - last_save_ >= interval_;
    if (due) {
      std::lock_guard lock(mutex_);
      if (checkpoint_.records.size() > saved_) save_locked();  // else the file on disk holds them all
      last_save_ = Clock::now();
    }
    return;
  }
  if (request == InterruptMode::checkpoint && waiting_for_states()) return;
  const int signal = interrupt_signal();
  request_interrupt(InterruptMode::abort, signal);  // the running realizations stop
  if (request != InterruptMode::checkpoint) throw Interrupted(signal);
  save();
  std::lock_guard lock(mutex_);
  const std::size_t n = checkpoint_.records.size();
  throw CheckpointTaken(signal, "checkpoint written: " + std::to_string(n) +
                                    (n == 1 ? " realization finished is" : " realizations finished are") +
                                    " kept in " + checkpoint_path(dir_).string() + states_note() +
                                    resume_hint(dir_));
}

// On a checkpoint request: whether the running realizations are still to
// reach a safe point and save there (for at most kStateGraceSeconds), or
// still writing.
void Checkpointer::request_seen() {
  std::lock_guard lock(mutex_);
  if (!asked_) asked_ = Clock::now();
}

bool Checkpointer::waiting_for_states() {
  std::lock_guard lock(mutex_);
  if (!asked_) asked_ = Clock::now();
  if (running_.empty()) return false;
  const double waited = std::chrono::duration<double>(Clock::now() - *asked_).count();
  return writing_ > 0 || waited < kStateGraceSeconds;
}

// What the states kept hold, for the message of a checkpoint request.
std::string Checkpointer::states_note() const {
  std::string text;
  for (const auto& [key, t] : states_) {
    const std::string who = "realization " + std::to_string(key.second);
    if (saved_on_request_.count(key))
      text += "; " + who + " saved at t = " + to_text(t, 6);
    else if (running_.count(key))
      text += "; " + who + " did not reach a safe point within " + to_text(kStateGraceSeconds) +
              " s: the last periodic checkpoint (t = " + to_text(t, 6) + ") is kept";
    else
      text += "; " + who + " at t = " + to_text(t, 6);
  }
  for (const Key& key : running_)
    if (!states_.count(key))
      text += "; realization " + std::to_string(key.second) + " did not reach a safe point within " +
              to_text(kStateGraceSeconds) + " s and starts again";
  return text + others_said_;
}

std::vector<RealizationRecord> Checkpointer::take_records() {
  std::lock_guard lock(mutex_);
  return std::exchange(checkpoint_.records, {});
}

void Checkpointer::save() {
  std::lock_guard lock(mutex_);
  save_locked();
}

// checkpoint.bin with every record; the states of the realizations new in it
// (saved by this process or by another rank of a job) are then stale, and
// removed. The first save of a new run replaces an earlier run's checkpoint
// (its running realizations' states and states files go first).
void Checkpointer::save_locked(bool fault) {
  if (!on_disk_ && !resuming_ && !job_rank_) {
    remove_run_states(dir_);
    remove_state_files(dir_);
  }
  for (const RealizationRecord& r : checkpoint_.records)  // on the disk before the record that needs them
    if (r.states_apart) {
      move_state_file(work_, dir_, r.ensemble);
      sync_state_file(state_file_path(dir_, r.ensemble));
    }
  checkpoint_.seconds = seconds_before_ + std::chrono::duration<double>(Clock::now() - started_).count();
  write_checkpoint(dir_, checkpoint_);
  on_disk_ = true;
  const std::size_t before = std::min(saved_, checkpoint_.records.size());
  saved_ = checkpoint_.records.size();
  last_save_ = Clock::now();
  for (std::size_t i = before; i < checkpoint_.records.size(); ++i) {
    const RealizationRecord& r = checkpoint_.records[i];
    states_.erase({r.ensemble, r.index});
    std::error_code ec;
    std::filesystem::remove(run_state_path(dir_, r.ensemble, r.index), ec);
  }
  if (fault) fault_point("checkpoint");
}

RealizationSaves::RealizationSaves(Checkpointer& owner, const WorkItem& item)
    : owner_(owner), item_(item), last_(Clock::now()) {
  std::lock_guard lock(owner_.mutex_);
  owner_.running_.insert({item.ensemble, item.index});
  if (owner_.job_rank_ && owner_.resuming_) owner_.find_state({item.ensemble, item.index});
}

RealizationSaves::~RealizationSaves() {
  std::lock_guard lock(owner_.mutex_);
  owner_.running_.erase({item_.ensemble, item_.index});
}

bool RealizationSaves::due() {
  return owner_.interval_ > Clock::duration::zero() && Clock::now() - last_ >= owner_.interval_;
}

std::optional<std::pair<double, double>> RealizationSaves::resumed_at() const {
  std::lock_guard lock(owner_.mutex_);
  const auto it = owner_.resumed_.find({item_.ensemble, item_.index});
  if (it == owner_.resumed_.end()) return std::nullopt;
  return it->second;
}

std::optional<std::string> RealizationSaves::resumed_sink() const {
  std::lock_guard lock(owner_.mutex_);
  const auto it = owner_.resumed_sinks_.find({item_.ensemble, item_.index});
  if (it == owner_.resumed_sinks_.end() || it->second.empty()) return std::nullopt;
  return it->second;
}

particles::RunCheckpoints RealizationSaves::checkpoints() {
  bool has_state;
  {
    std::lock_guard lock(owner_.mutex_);
    has_state = owner_.resumed_.count({item_.ensemble, item_.index}) > 0;
  }
  if (has_state && !resume_)
    resume_ =
        open_run_state(run_state_path(owner_.dir_, item_.ensemble, item_.index), owner_.states_checked_);
  return {this, resume_.get()};
}

// The checkpoint file first, if none is on disk yet: a state is resumed through it.
void RealizationSaves::save(double t, double fraction,
                            const std::function<void(particles::RunStateWriter&)>& write) {
  const Checkpointer::Key key{item_.ensemble, item_.index};
  RunStateHeader header = owner_.identity_;
  header.ensemble = item_.ensemble, header.index = item_.index, header.time = t, header.fraction = fraction;
  {
    std::lock_guard lock(owner_.mutex_);
    if (!owner_.on_disk_) owner_.save_locked(false);  // the checkpoint is complete with the state
    ++owner_.writing_;
  }
  struct Done {
    Checkpointer& c;
    ~Done() {
      std::lock_guard lock(c.mutex_);
      --c.writing_;
    }
  } done{owner_};
  if (sink_) header.sink = sink_();  // beside the checkpoint, synced before the state that refers to it
  write_run_state(owner_.dir_, header, write);
  last_ = Clock::now();
  {
    std::lock_guard lock(owner_.mutex_);
    owner_.states_[key] = t;
    if (interrupt_requested() == InterruptMode::checkpoint) owner_.saved_on_request_.insert(key);
  }
  fault_point(owner_.job_rank_ ? "state" : "checkpoint");
}

}  // namespace shockgas::app
