#pragma once
// Progress of a run on stderr: a redrawn bar when stderr is a terminal, one
// line per 10 % otherwise, each with the stage's fraction, which realization
// of how many an ensemble is at, and the time left, eta = elapsed * (1 - f) /
// (f - f0) from the rate measured since the stage's first progress f0, and,
// where the stage counts collisions, their rate since then; silent
// during the first second, so that short runs print nothing. Between the
// measured stages, the phases of a run whose progress is not measured (the
// comparison, the result files, the plots) each say what the run is doing, on
// one line completed with their wall time; a run that said anything ends with
// one line that times the phases too short to have a line of their own.
#include <chrono>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "shockgas/core/progress.hpp"

namespace shockgas::app {

class ProgressBar {
 public:
  // Told of every update (stage, fraction, simulated time), under the bar's lock.
  using Listener = std::function<void(const std::string& stage, double fraction, double sim_time)>;

  using Clock = std::chrono::steady_clock;
  // enabled = false prints nothing (tests, --quiet); listener, if any, hears
  // every update whether or not anything is printed; now, if given, is the
  // clock (a scripted one in tests), else Clock::now.
  explicit ProgressBar(bool enabled = true, Listener listener = {},
                       std::function<Clock::time_point()> now = {});
  // Ends the current phase: its time, or "stopped" when an exception unwinds.
  ~ProgressBar();
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  // Starts a stage ("particles", "continuum/godunov"); resets the fraction.
  // realizations > 1: the stage is an ensemble of that many, each an equal
  // share of its fraction, and its lines say "realization k of n".
  void stage(const std::string& name, std::size_t realizations = 0);
  // fraction of the stage done, in [0, 1]; sim_time the simulated time reached;
  // events the collisions done so far (0: not counted; else the lines give
  // their rate since the stage's first progress). Thread-safe.
  void update(double fraction, double sim_time, std::uint64_t events = 0);
  // Finishes the current line, if a bar was drawn.
  void finish();

  // Starts a phase (ending the one before): "NAME ... " on a line of its own,
  // completed when the phase ends (end_phase(), the next phase, the bar's end)
  // with its wall time, "NAME ... 3.9 s", or "stopped" when an exception ends it.
  // Within the first second of the process nothing is printed; a phase still
  // running at its end is announced then. A stage started within a phase (a
  // solver's bar) has its own lines, and the phase's time then follows as
  // "NAME: 3.9 s". The listener does not hear of phases.
  void phase(const std::string& name);
  void end_phase();
  // Every phase ended so far, in order, with its wall time in seconds, whether
  // or not it was said (--quiet, the first second): for report.md.
  const std::vector<std::pair<std::string, double>>& phase_times() const { return timed_; }
  // Names every phase after this one as about `what` ("plots (r=0.5)"): a
  // sweep's variant.
  void name_phases(const std::string& what) { about_ = " (" + what + ")"; }
  // Message lines (each with its newline; none: nothing) on stderr, after the
  // line of a phase or a bar is ended, so that they never land in the middle of one.
  void say(const std::string& line);

  // A callback for the engines that forwards to update().
  ProgressCallback callback();

 private:
  void draw(double fraction, double sim_time, std::uint64_t events);
  std::string eta_text(double fraction, Clock::time_point now) const;  // "12 s", or "?" before any progress
  std::string rate_text(std::uint64_t events, Clock::time_point now) const;  // "12.3 M collisions/s", or ""
  std::string realization_text(double fraction) const;                       // "realization 3 of 8", or ""
  void say_short_phases();                                                   // the final timing line
  void end_line();                                                           // under mutex_
  void end_phase(const char* outcome);  // outcome: nullptr for the wall time
  void announce();                      // under mutex_
  bool enabled_, tty_;
  Listener listener_;
  std::function<Clock::time_point()> now_;
  std::string stage_;
  std::size_t realizations_ = 0;
  Clock::time_point start_, last_draw_;
  int last_decile_ = -1;
  double last_time_ = 0;
  // The stage's first update with any progress: where this process took it up
  // (its first steps, or a resumed run's checkpoint), from which the rate and
  // the remaining time are measured.
  struct Base {
    Clock::time_point clock;
    double fraction, time;
    std::uint64_t events;
  };
  std::optional<Base> base_;
  bool drawn_ = false;
  // The current phase: its name and start, whether its line was printed and
  // is still open; a thread announces it at the end of the process's first second.
  std::string phase_, about_;
  Clock::time_point phase_start_;
  bool in_phase_ = false, announced_ = false, line_open_ = false;
  std::vector<std::pair<std::string, double>> timed_;
  std::vector<bool> said_;  // per timed phase: whether its own line gave its time
  bool spoke_ = false;      // anything printed
  std::thread announcer_;
  std::condition_variable phase_ended_;
  int unwinding_ = 0;  // std::uncaught_exceptions() when constructed
  std::mutex mutex_;   // engines may report from worker threads
};

}  // namespace shockgas::app
