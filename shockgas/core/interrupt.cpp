#include "shockgas/core/interrupt.hpp"

#include <atomic>

namespace shockgas {

namespace {
std::atomic<int> g_mode{0};
std::atomic<int> g_signal{0};
static_assert(std::atomic<int>::is_always_lock_free, "request_interrupt must be async-signal-safe");
}  // namespace

void request_interrupt(InterruptMode mode, int signal_number) noexcept {
  const int wanted = static_cast<int>(mode);
  int current = g_mode.load(std::memory_order_relaxed);
  while (wanted > current && !g_mode.compare_exchange_weak(current, wanted, std::memory_order_relaxed)) {
  }
  if (signal_number != 0) g_signal.store(signal_number, std::memory_order_relaxed);
}

InterruptMode interrupt_requested() noexcept {
  return static_cast<InterruptMode>(g_mode.load(std::memory_order_relaxed));
}

int interrupt_signal() noexcept { return g_signal.load(std::memory_order_relaxed); }

void clear_interrupt() noexcept {
  g_mode.store(0, std::memory_order_relaxed);
  g_signal.store(0, std::memory_order_relaxed);
}

void throw_if_aborted() {
  if (interrupt_requested() == InterruptMode::abort) throw Interrupted(interrupt_signal());
}

}  // namespace shockgas
