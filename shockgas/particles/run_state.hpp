#pragma once
// Saving a particle run in progress and continuing it from the save.
//
// At every safe point (RunStop: the end of a time window or sub-window, or a
// check point of the global queue) the run asks RunSaves::due(); when it says
// yes, the run hands save() a function that writes its whole state: the bodies
// as they are (each at its own time: nothing is moved to a common time, so
// saving changes nothing), the pair times and the event queue's nodes, the
// window scheduler's state (plan, cuts, domains and their trees, rate,
// velocity range, the global/window choice, counters), the counts and energy,
// and the records taken so far. A run given that state as `resume` continues
// from it and ends with the results of the run that saved it, bit for bit
// (tests/particles/test_run_state.cpp), whatever the number of threads.
//
// A checkpoint request (InterruptMode::checkpoint) with saves: the run saves at
// its next safe point, or inside a sub-window of the time windows that holds no
// sample time (each domain where it is: they are independent until the
// sub-window ends, and the resumed run runs that sub-window on), then throws
// Interrupted: the save is what goes on, not a result.
//
// The bytes are in the machine's order and layout: a state is resumed by the
// same build with the same initial condition and parameters; the caller checks
// that (shockgas/app/records/run_state_file.hpp does). The hull solver has no safe points inside
// a run: it never saves, and refuses a state.
#include <cstddef>
#include <functional>

namespace shockgas::particles {

// Where the bytes of a state go, in order.
class RunStateWriter {
 public:
  virtual ~RunStateWriter() = default;
  virtual void write(const void* data, std::size_t bytes) = 0;
};

// Where they come back from; read() throws RunError past the end of the state.
class RunStateReader {
 public:
  virtual ~RunStateReader() = default;
  virtual void read(void* data, std::size_t bytes) = 0;
  // Bytes left: a count read from the state is checked against it before
  // anything of that size is allocated.
  virtual std::size_t remaining() const = 0;
};

// The owner of a run's saves (the run calls it from the run's own thread).
class RunSaves {
 public:
  virtual ~RunSaves() = default;
  // Asked at every safe point: whether to save there.
  virtual bool due() = 0;
  // write(out) writes the whole state to out, once, during this call; t: the
  // simulated time reached; fraction: the share of the run's work done.
  virtual void save(double t, double fraction, const std::function<void(RunStateWriter&)>& write) = 0;
};

struct RunCheckpoints {
  RunSaves* saves = nullptr;         // none: the run never saves
  RunStateReader* resume = nullptr;  // a state saved by this run: continue from it
};

}  // namespace shockgas::particles
