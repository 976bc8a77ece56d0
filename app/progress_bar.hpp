#pragma once
// Progress of a run on stderr: a redrawn bar when stderr is a terminal, one
// line per 10 % otherwise; silent during the first second, so that short runs
// print nothing.
#include <chrono>
#include <functional>
#include <mutex>
#include <string>

#include "shockgas/core/progress.hpp"

namespace shockgas::app {

class ProgressBar {
 public:
  // Told of every update (stage, fraction, simulated time), under the bar's lock.
  using Listener = std::function<void(const std::string& stage, double fraction, double sim_time)>;

  // enabled = false prints nothing (tests, --quiet); listener, if any, hears
  // every update whether or not anything is printed.
  explicit ProgressBar(bool enabled = true, Listener listener = {});
  ~ProgressBar();

  // Starts a stage ("particles", "continuum/godunov"); resets the fraction.
  void stage(const std::string& name);
  // fraction of the stage done, in [0, 1]; sim_time the simulated time reached.
  // Thread-safe.
  void update(double fraction, double sim_time);
  // Finishes the current line, if a bar was drawn.
  void finish();

  // A callback for the engines that forwards to update().
  ProgressCallback callback();

 private:
  using Clock = std::chrono::steady_clock;
  void draw(double fraction, double sim_time);
  bool enabled_, tty_;
  Listener listener_;
  std::string stage_;
  Clock::time_point start_, last_draw_;
  int last_decile_ = -1;
  double last_time_ = 0;
  bool drawn_ = false;
  std::mutex mutex_;  // engines may report from worker threads
};

}  // namespace shockgas::app
