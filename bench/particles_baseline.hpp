#pragma once
// The straightforward event-driven engine, kept as the speed baseline of
// particles_bench: equal-mass particles on a ring, a std::priority_queue of pair
// events, stale events skipped by per-particle collision counters (lazy
// invalidation). Same physics as shockgas::particles (restitution r, elastic
// below delta), and the same temperature at the same sample times as its
// recorder; nothing else observed.
#include <cmath>
#include <cstdint>
#include <limits>
#include <queue>
#include <vector>

#include "shockgas/core/bodies.hpp"
#include "shockgas/particles/collision.hpp"

namespace shockgas::bench {

class BaselineEngine {
 public:
  BaselineEngine(const Bodies& b, double L, double r, double delta)
      : L_(L), r_(r), delta_(delta), x_(b.x), v_(b.v), t_(b.size(), 0.0), stamp_(b.size(), 0) {
    for (std::size_t i = 0; i < size(); ++i) predict(i);
  }

  // Runs every collision at time <= t_stop; returns the collisions so far.
  std::uint64_t run_until(double t_stop) {
    while (!queue_.empty() && queue_.top().time <= t_stop) {
      const Event e = queue_.top();
      queue_.pop();
      const std::size_t j = right(e.slot);
      if (e.stamp_left != stamp_[e.slot] || e.stamp_right != stamp_[j]) continue;  // stale
      collide(e.slot, j, e.time);
      ++done_;
      predict(left(e.slot));
      predict(e.slot);
      predict(j);
    }
    return done_;
  }

  // Temperature <v^2> - <v>^2 (two passes, as the recorder).
  double temperature() const {
    double momentum = 0;
    for (double v : v_) momentum += v;
    const double mean = momentum / static_cast<double>(size());
    double T = 0;
    for (double v : v_) T += (v - mean) * (v - mean);
    return T / static_cast<double>(size());
  }

 private:
  struct Event {
    double time;
    std::uint32_t slot;
    std::uint32_t stamp_left, stamp_right;
    bool operator<(const Event& o) const { return time > o.time; }  // min-heap
  };

  std::size_t size() const { return x_.size(); }
  std::size_t right(std::size_t i) const { return i + 1 == size() ? 0 : i + 1; }
  std::size_t left(std::size_t i) const { return i == 0 ? size() - 1 : i - 1; }

  void predict(std::size_t i) {
    const std::size_t j = right(i);
    const double g = v_[i] - v_[j];
    if (g <= 0) return;
    const double tm = std::max(t_[i], t_[j]);
    const double shift = j == 0 ? L_ : 0.0;
    const double gap = (x_[j] + v_[j] * (tm - t_[j]) + shift) - (x_[i] + v_[i] * (tm - t_[i]));
    queue_.push({tm + std::max(gap, 0.0) / g, static_cast<std::uint32_t>(i), stamp_[i], stamp_[j]});
  }

  void collide(std::size_t i, std::size_t j, double t) {
    x_[i] += v_[i] * (t - t_[i]);
    t_[i] = t;
    x_[j] = j == 0 ? x_[i] - L_ : x_[i];
    t_[j] = t;
    const double g = v_[i] - v_[j];
    particles::bounce_equal(v_[i], v_[j], 1.0, g < delta_ ? 1.0 : r_);
    ++stamp_[i];
    ++stamp_[j];
  }

  double L_, r_, delta_;
  std::vector<double> x_, v_, t_;
  std::vector<std::uint32_t> stamp_;
  std::priority_queue<Event> queue_;
  std::uint64_t done_ = 0;
};

}  // namespace shockgas::bench
