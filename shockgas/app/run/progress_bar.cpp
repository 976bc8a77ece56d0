#include "shockgas/app/run/progress_bar.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>

#include "shockgas/app/files/fault.hpp"
#include "shockgas/core/thread_start.hpp"

namespace shockgas::app {

namespace {

// Nothing is printed before the process has run this long (a bar: before its
// stage has): a run of the command that ends sooner prints nothing.
constexpr std::chrono::seconds kSilent{1};
const std::chrono::steady_clock::time_point process_start = std::chrono::steady_clock::now();

}  // namespace

ProgressBar::ProgressBar(bool enabled, Listener listener, std::function<Clock::time_point()> now)
    : enabled_(enabled),
      tty_(isatty(STDERR_FILENO) != 0),
      listener_(std::move(listener)),
      now_(now ? std::move(now) : [] { return Clock::now(); }),
      start_(now_()),
      last_draw_(start_),
      unwinding_(std::uncaught_exceptions()) {}

ProgressBar::~ProgressBar() {
  end_phase(std::uncaught_exceptions() > unwinding_ ? "stopped" : nullptr);
  finish();
  say_short_phases();
}

void ProgressBar::say_short_phases() {
  if (!enabled_ || !spoke_) return;
  std::string line;
  char seconds[32];
  for (std::size_t i = 0; i < timed_.size(); ++i) {
    if (said_[i]) continue;
    std::snprintf(seconds, sizeof seconds, " %.2f s", timed_[i].second);
    line += (line.empty() ? "" : "; ") + timed_[i].first + seconds;  // names hold commas
  }
  if (!line.empty()) std::fprintf(stderr, "phases without a line of their own: %s\n", line.c_str());
}

void ProgressBar::stage(const std::string& name, std::size_t realizations) {
  finish();
  stage_ = name;
  realizations_ = realizations;
  start_ = last_draw_ = now_();
  last_decile_ = -1;
  last_time_ = 0;
  base_ = std::nullopt;
  if (listener_) listener_(stage_, 0.0, 0.0);
}

void ProgressBar::update(double fraction, double sim_time, std::uint64_t events) {
  fault_point("compute");
  if (!enabled_ && !listener_) return;
  std::lock_guard<std::mutex> lock(mutex_);
  if (listener_) listener_(stage_, fraction, sim_time);
  if (!enabled_) return;
  const auto now = now_();
  // The base is the first update that reports any progress: a resumed run's
  // workers report where they took up only after the first poll, which says 0.
  if (!base_ && (fraction > 0 || sim_time > 0))
    base_ = Base{now, std::clamp(fraction, 0.0, 1.0), sim_time, events};
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  if (elapsed < 1.0) return;  // short runs print nothing
  fraction = std::clamp(fraction, 0.0, 1.0);
  if (tty_) {
    if (std::chrono::duration<double>(now - last_draw_).count() < 0.1 && fraction < 1.0) return;
    last_draw_ = now;
    draw(fraction, sim_time, events);
  } else {
    const int decile = static_cast<int>(std::floor(10 * fraction));
    if (decile <= last_decile_) return;
    last_decile_ = decile;
    draw(fraction, sim_time, events);
  }
}

// Rate and remaining time from the work done since the first update: a
// resumed run starts where its checkpoint was, not at 0.
std::string ProgressBar::eta_text(double fraction, Clock::time_point now) const {
  const Base base = base_.value_or(Base{now, fraction, 0.0, 0});
  const double since = std::chrono::duration<double>(now - base.clock).count();
  const double done = fraction - base.fraction;
  if (!(done > 0)) return "?";  // unknown until this process has done some of the work
  char eta[32];
  std::snprintf(eta, sizeof eta, "%.0f s", since * (1 - fraction) / done);
  return eta;
}

// The collisions per second since the first update: what an engine's speed is
// quoted in, where simulated time per second falls as a gas slows down.
std::string ProgressBar::rate_text(std::uint64_t events, Clock::time_point now) const {
  if (!base_ || events <= base_->events) return "";
  const double since = std::chrono::duration<double>(now - base_->clock).count();
  if (!(since > 0)) return "";
  const double rate = static_cast<double>(events - base_->events) / since;
  char text[48];
  if (rate >= 1e6)
    std::snprintf(text, sizeof text, "%.1f M collisions/s", rate / 1e6);
  else if (rate >= 1e3)
    std::snprintf(text, sizeof text, "%.1f k collisions/s", rate / 1e3);
  else
    std::snprintf(text, sizeof text, "%.0f collisions/s", rate);
  return text;
}

// Realizations are equal shares of an ensemble's fraction: the one under way is
// the next after those whose shares are done (with several at once, the lowest).
std::string ProgressBar::realization_text(double fraction) const {
  if (realizations_ < 2) return "";
  const auto n = static_cast<double>(realizations_);
  const auto k = static_cast<std::size_t>(std::min(n, std::floor(fraction * n) + 1));
  return "realization " + std::to_string(k) + " of " + std::to_string(realizations_);
}

void ProgressBar::draw(double fraction, double sim_time, std::uint64_t events) {
  const auto now = now_();
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const std::string eta = eta_text(fraction, now);
  const std::string rate = rate_text(events, now);
  // An ensemble's simulated time is that of its furthest realization: not a measure of its progress.
  std::string which = realization_text(fraction);
  if (which.empty()) {
    char t[48];
    std::snprintf(t, sizeof t, tty_ ? "t = %-10.4g" : "t = %.4g", sim_time);
    which = t;
  }
  char line[240];
  if (tty_) {
    constexpr int width = 30;
    const int filled = static_cast<int>(width * fraction);
    std::string bar(filled, '#');
    bar.resize(width, '.');
    // Fixed widths: a shorter line than the last would leave its end on the screen.
    std::snprintf(line, sizeof line, "\r%-18s [%s] %3.0f%%  %s  eta %-6s  %-20s", stage_.c_str(), bar.c_str(),
                  100 * fraction, which.c_str(), eta.c_str(), rate.c_str());
  } else {
    std::snprintf(line, sizeof line, "%s: %3.0f%%  %s  elapsed %.1f s  eta %s%s%s\n", stage_.c_str(),
                  100 * fraction, which.c_str(), elapsed, eta.c_str(), rate.empty() ? "" : "  ",
                  rate.c_str());
  }
  spoke_ = true;
  if (line_open_) std::fputs("\n", stderr);  // the phase's time follows on a line of its own
  line_open_ = false;
  std::fputs(line, stderr);
  std::fflush(stderr);
  drawn_ = tty_;
}

void ProgressBar::finish() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (drawn_) std::fputs("\n", stderr);
  drawn_ = false;
}

void ProgressBar::end_line() {
  if (drawn_ || line_open_) std::fputs("\n", stderr);
  drawn_ = line_open_ = false;
}

void ProgressBar::phase(const std::string& name) {
  end_phase(nullptr);
  std::lock_guard<std::mutex> lock(mutex_);
  phase_ = name + about_;
  phase_start_ = now_();
  in_phase_ = true;  // timed even when nothing is said
  if (!enabled_) return;
  if (phase_start_ - process_start >= kSilent) {
    announce();
    return;
  }
  announcer_ = start_thread([this] {
    std::unique_lock<std::mutex> held(mutex_);
    if (!phase_ended_.wait_until(held, process_start + kSilent, [this] { return !in_phase_; })) announce();
  });
}

void ProgressBar::announce() {
  end_line();
  std::fprintf(stderr, "%s ... ", phase_.c_str());
  std::fflush(stderr);
  announced_ = line_open_ = spoke_ = true;
}

void ProgressBar::end_phase() { end_phase(nullptr); }

void ProgressBar::end_phase(const char* outcome) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    const double seconds = std::chrono::duration<double>(now_() - phase_start_).count();
    if (in_phase_) {
      timed_.emplace_back(phase_, seconds);
      said_.push_back(announced_ && enabled_);
    }
    if (in_phase_ && announced_) {
      char done[32];
      std::snprintf(done, sizeof done, "%.1f s", seconds);
      if (!line_open_) {
        end_line();
        std::fprintf(stderr, "%s: ", phase_.c_str());
      }
      std::fprintf(stderr, "%s\n", outcome ? outcome : done);
      std::fflush(stderr);
    }
    in_phase_ = announced_ = line_open_ = false;
  }
  phase_ended_.notify_all();
  if (announcer_.joinable()) announcer_.join();
}

void ProgressBar::say(const std::string& line) {
  if (line.empty()) return;
  std::lock_guard<std::mutex> lock(mutex_);
  end_line();
  std::fputs(line.c_str(), stderr);
  std::fflush(stderr);
}

ProgressCallback ProgressBar::callback() {
  return
      [this](double fraction, double sim_time, std::uint64_t events) { update(fraction, sim_time, events); };
}

}  // namespace shockgas::app
