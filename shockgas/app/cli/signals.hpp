#pragma once
// The command line's signal handlers: the host side of the one signal design
// (shockgas/core/interrupt.hpp). SIGINT, SIGTERM and SIGHUP (unless ignored
// from the start: nohup) only call request_interrupt(abort), or a checkpoint
// request while a run keeps checkpoints; SIGPIPE is ignored (a closed stderr
// ends no run);
// the engine, the solvers, the writers and the plotting wait poll it, stop at a
// safe point and throw Interrupted, and the run's staging directory is removed
// on the way out (run_directory.hpp). A second signal of the same kind while the
// first is being honoured ends the process at once, as without a handler: the
// next run clears what it left.
namespace shockgas::app {

// Installs the handlers for its lifetime (the previous dispositions come back
// after). One at a time, on the command line only: the library never installs
// handlers.
class InterruptHandlers {
 public:
  InterruptHandlers();
  ~InterruptHandlers();
  InterruptHandlers(const InterruptHandlers&) = delete;
  InterruptHandlers& operator=(const InterruptHandlers&) = delete;
};

// After the run stopped on a signal, the process ends the way a shell expects
// of a program killed by it (status 128 + signal, and a loop around the command
// stops): the default disposition restored and the signal raised again.
// Returns (does nothing) when no signal was received.
void end_as_signalled();

}  // namespace shockgas::app
