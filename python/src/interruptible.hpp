#pragma once
// Long computations called from Python: the GIL released, Ctrl-C honoured,
// progress shown, and no signal handler left installed.
//
// The computation runs on a worker thread while the calling thread waits. Every
// 50 ms the waiting thread takes the GIL, runs Python's pending signal handlers
// (PyErr_CheckSignals) and hands the latest progress to the caller's callback.
// When a handler raises (KeyboardInterrupt on Ctrl-C: Python's own handler), the
// computation is asked to stop through the one signal design of shockgas,
// request_interrupt(InterruptMode::abort) (shockgas/core/interrupt.hpp): the engine and
// the solvers poll it at their safe points and throw Interrupted, which unwinds
// everything (a result directory's temporary files are removed on the way). The
// worker is joined and the Python exception raised. The last computation of the
// process to end forgets the request, so one Ctrl-C stops every computation
// running then, and none started after them all. SIGTERM and SIGHUP, where
// they would end the process at once (their default disposition), stop the
// computations the same way while any runs, and end the process once they
// have unwound (a run directory's staging directory and lock removed).
#include <pybind11/pybind11.h>

#include <functional>
#include <mutex>
#include <optional>
#include <string>

namespace shockgas::python {

namespace py = pybind11;

// The latest progress report, passed from the computation's threads to the
// waiting one.
class ProgressRelay {
 public:
  struct Report {
    std::string stage;    // "particles", "continuum/<solver>", or the function's name
    double fraction = 0;  // of the stage, in [0, 1]
    double sim_time = 0;  // simulated time reached [time]
  };
  // Any thread.
  void report(const std::string& stage, double fraction, double sim_time);
  // The latest report if there was one since the last take().
  std::optional<Report> take();

 private:
  std::mutex mutex_;
  Report latest_;
  bool fresh_ = false;
};

// Runs work(relay) as described above; `progress` is None or a callable
// progress(stage, fraction, time) called on the calling thread. Exceptions of
// `work` are raised here (InputError as ValueError, ...; errors.hpp).
void run_interruptible(const std::function<void(ProgressRelay&)>& work, const py::object& progress);

// The same for a computation with a result (computed on the worker, handed back).
template <class R>
R run_interruptible(const std::function<R(ProgressRelay&)>& work, const py::object& progress) {
  std::optional<R> result;
  run_interruptible([&](ProgressRelay& relay) { result.emplace(work(relay)); }, progress);
  return std::move(*result);
}

}  // namespace shockgas::python
