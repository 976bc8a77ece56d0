#include "interruptible.hpp"

#include <chrono>
#include <condition_variable>
#include <csignal>
#include <exception>
#include <thread>

#include "shockgas/core/interrupt.hpp"

namespace shockgas::python {

namespace {

constexpr auto kPollInterval = std::chrono::milliseconds(50);

// SIGTERM and SIGHUP at their default disposition would end the process at
// once, leaving a run directory's staging directory and lock behind: while a
// computation runs they only request an interrupt, and once the last
// computation has unwound (its temporary files removed) the process ends by
// the signal after all, as it was asked to. A disposition Python or the user
// set is left alone (its handler runs in PyErr_CheckSignals, below).
constexpr int kTermination[] = {SIGTERM, SIGHUP};
struct sigaction g_default[2];
bool g_ours[2] = {false, false};

extern "C" void on_termination(int sig) { request_interrupt(InterruptMode::abort, sig); }

void take_termination_signals() {
  struct sigaction action {};
  action.sa_handler = on_termination;
  sigemptyset(&action.sa_mask);
  for (int i = 0; i < 2; ++i) {
    sigaction(kTermination[i], nullptr, &g_default[i]);
    g_ours[i] = g_default[i].sa_handler == SIG_DFL;
    if (g_ours[i]) sigaction(kTermination[i], &action, nullptr);
  }
}

// Restores the dispositions; the signal that ended the computations, if one
// of them did, is raised again.
void give_back_termination_signals() {
  const int received = interrupt_signal();
  for (int i = 0; i < 2; ++i)
    if (g_ours[i]) sigaction(kTermination[i], &g_default[i], nullptr);
  for (int i = 0; i < 2; ++i)
    if (g_ours[i] && received == kTermination[i]) std::raise(received);
}

// Counts the computations running in this process; the first takes the
// termination signals, the last gives them back and forgets a pending
// interrupt request.
class Activity {
 public:
  Activity() {
    std::lock_guard lock(mutex());
    if (count()++ == 0) take_termination_signals();
  }
  ~Activity() {
    std::lock_guard lock(mutex());
    if (--count() > 0) return;
    give_back_termination_signals();
    clear_interrupt();
  }
  Activity(const Activity&) = delete;
  Activity& operator=(const Activity&) = delete;

 private:
  static std::mutex& mutex() {
    static std::mutex m;
    return m;
  }
  static int& count() {
    static int n = 0;
    return n;
  }
};

// With the GIL: runs the pending signal handlers, then hands on the latest
// progress. Returns the Python exception either raised, if any.
std::optional<py::error_already_set> look_in(ProgressRelay& relay, const py::object& progress) {
  if (PyErr_CheckSignals() != 0) return py::error_already_set();
  if (progress.is_none()) return std::nullopt;
  if (auto r = relay.take()) {
    try {
      progress(r->stage, r->fraction, r->sim_time);
    } catch (py::error_already_set& e) {
      return e;
    }
  }
  return std::nullopt;
}

}  // namespace

void ProgressRelay::report(const std::string& stage, double fraction, double sim_time) {
  std::lock_guard lock(mutex_);
  latest_ = {stage, fraction, sim_time};
  fresh_ = true;
}

std::optional<ProgressRelay::Report> ProgressRelay::take() {
  std::lock_guard lock(mutex_);
  if (!fresh_) return std::nullopt;
  fresh_ = false;
  return latest_;
}

void run_interruptible(const std::function<void(ProgressRelay&)>& work, const py::object& progress) {
  Activity activity;  // outlives the worker
  ProgressRelay relay;
  std::exception_ptr error;
  std::optional<py::error_already_set> raised;
  std::mutex mutex;
  std::condition_variable finished;
  bool done = false;
  {
    py::gil_scoped_release nogil;
    std::thread worker([&] {
      try {
        work(relay);
      } catch (...) {
        error = std::current_exception();
      }
      std::lock_guard lock(mutex);
      done = true;
      finished.notify_one();
    });
    std::unique_lock lock(mutex);
    while (!finished.wait_for(lock, kPollInterval, [&] { return done; })) {
      lock.unlock();
      if (!raised) {
        py::gil_scoped_acquire gil;
        raised = look_in(relay, progress);
        if (raised) request_interrupt(InterruptMode::abort);
      }
      lock.lock();
    }
    lock.unlock();
    worker.join();
  }
  if (raised) throw std::move(*raised);
  if (error) std::rethrow_exception(error);
  if (!progress.is_none())
    if (auto r = relay.take()) progress(r->stage, r->fraction, r->sim_time);
}

}  // namespace shockgas::python
