#pragma once
// Cooperative interruption: the one signal design of shockgas.
//
// The library never installs a signal handler: the host owns signals (the
// command line, a Python session, an MPI launcher). The host's handler, or any
// thread, calls request_interrupt(); long computations (the particle engine,
// the continuum solvers, the writers) poll interrupt_requested() at their safe
// points and stop there:
//
//  * InterruptMode::abort       stop as soon as possible (inside a time window
//                               of the engine too); the partial result is
//                               discarded: throw Interrupted.
//  * InterruptMode::checkpoint  finish the current step to a state from which
//                               the run can be resumed (the engine: the end of
//                               the current window), save it, then throw
//                               Interrupted.
//
// request_interrupt() is async-signal-safe: it stores into lock-free atomics.
#include <stdexcept>
#include <string>

namespace shockgas {

// Ordered by strength: a stronger request replaces a weaker one.
enum class InterruptMode : int { none = 0, checkpoint = 1, abort = 2 };

// Asks every running computation of this process to stop. signal_number: the
// signal that caused it (0 for none), kept so that the host can exit with the
// usual status 128 + signal. A later request never weakens an earlier one
// (abort wins over checkpoint).
void request_interrupt(InterruptMode mode, int signal_number = 0) noexcept;

// The pending request (InterruptMode::none if none); cheap: one relaxed load.
InterruptMode interrupt_requested() noexcept;
// The signal given with the pending request, or 0.
int interrupt_signal() noexcept;

// Forgets the pending request (a host that handled it and goes on).
void clear_interrupt() noexcept;

// Thrown by a computation that stopped on request. Not an error of the input
// or of the run: the host decides what to report (exit status 128 + signal on
// the command line, KeyboardInterrupt in Python).
class Interrupted : public std::runtime_error {
 public:
  explicit Interrupted(int signal_number = 0)
      : std::runtime_error("interrupted" +
                           (signal_number ? " by signal " + std::to_string(signal_number) : std::string())),
        signal_(signal_number) {}
  int signal_number() const { return signal_; }

 private:
  int signal_;
};

// Throws Interrupted if an abort is pending (a checkpoint request is left for
// the caller that can honour it).
void throw_if_aborted();

}  // namespace shockgas
