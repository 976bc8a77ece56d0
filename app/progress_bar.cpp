#include "progress_bar.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "fault.hpp"

namespace shockgas::app {

ProgressBar::ProgressBar(bool enabled, Listener listener)
    : enabled_(enabled),
      tty_(isatty(STDERR_FILENO) != 0),
      listener_(std::move(listener)),
      start_(Clock::now()),
      last_draw_(start_) {}

ProgressBar::~ProgressBar() { finish(); }

void ProgressBar::stage(const std::string& name) {
  finish();
  stage_ = name;
  start_ = last_draw_ = Clock::now();
  last_decile_ = -1;
  last_time_ = 0;
  if (listener_) listener_(stage_, 0.0, 0.0);
}

void ProgressBar::update(double fraction, double sim_time) {
  fault_point("compute");
  if (!enabled_ && !listener_) return;
  std::lock_guard<std::mutex> lock(mutex_);
  if (listener_) listener_(stage_, fraction, sim_time);
  if (!enabled_) return;
  const auto now = Clock::now();
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  if (elapsed < 1.0) return;  // short runs print nothing
  fraction = std::clamp(fraction, 0.0, 1.0);
  if (tty_) {
    if (std::chrono::duration<double>(now - last_draw_).count() < 0.1 && fraction < 1.0) return;
    last_draw_ = now;
    draw(fraction, sim_time);
  } else {
    const int decile = static_cast<int>(std::floor(10 * fraction));
    if (decile <= last_decile_) return;
    last_decile_ = decile;
    draw(fraction, sim_time);
  }
}

void ProgressBar::draw(double fraction, double sim_time) {
  const double elapsed = std::chrono::duration<double>(Clock::now() - start_).count();
  const double rate = elapsed > 0 ? sim_time / elapsed : 0;
  const double eta = fraction > 0 ? elapsed * (1 - fraction) / fraction : 0;
  char line[200];
  if (tty_) {
    constexpr int width = 30;
    const int filled = static_cast<int>(width * fraction);
    std::string bar(filled, '#');
    bar.resize(width, '.');
    std::snprintf(line, sizeof line, "\r%-18s [%s] %3.0f%%  t = %-10.4g  %.3g time units/s  eta %.0f s  ",
                  stage_.c_str(), bar.c_str(), 100 * fraction, sim_time, rate, eta);
  } else {
    std::snprintf(line, sizeof line, "%s: %3.0f%%  t = %.4g  %.3g time units/s  elapsed %.1f s\n", stage_.c_str(),
                  100 * fraction, sim_time, rate, elapsed);
  }
  std::fputs(line, stderr);
  std::fflush(stderr);
  drawn_ = tty_;
}

void ProgressBar::finish() {
  if (drawn_) std::fputs("\n", stderr);
  drawn_ = false;
}

ProgressCallback ProgressBar::callback() {
  return [this](double fraction, double sim_time) { update(fraction, sim_time); };
}

}  // namespace shockgas::app
