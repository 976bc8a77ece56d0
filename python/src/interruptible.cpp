#include "interruptible.hpp"

#include <chrono>
#include <condition_variable>
#include <exception>
#include <thread>

#include "shockgas/core/interrupt.hpp"

namespace shockgas::python {

namespace {

constexpr auto kPollInterval = std::chrono::milliseconds(50);

// Counts the computations running in this process; the last one to end
// forgets a pending interrupt request.
class Activity {
 public:
  Activity() {
    std::lock_guard lock(mutex());
    ++count();
  }
  ~Activity() {
    std::lock_guard lock(mutex());
    if (--count() == 0) clear_interrupt();
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
