#include "shockgas/app/cli/signals.hpp"

#include <csignal>
#include <cstdio>
#include <iostream>

#include "shockgas/app/ensemble/checkpointer.hpp"
#include "shockgas/core/interrupt.hpp"

namespace shockgas::app {

namespace {

constexpr int kSignals[] = {SIGINT, SIGTERM};
struct sigaction g_previous[2];

extern "C" void on_interrupt(int sig) {
  if (interrupt_signal() == sig) {  // the second one: stop now
    std::signal(sig, SIG_DFL);
    std::raise(sig);
    return;
  }
  // A run that keeps checkpoints saves one and stops (checkpointer.hpp); any other stops at once.
  request_interrupt(signals_take_checkpoints() ? InterruptMode::checkpoint : InterruptMode::abort, sig);
}

}  // namespace

InterruptHandlers::InterruptHandlers() {
  clear_interrupt();
  struct sigaction action {};
  action.sa_handler = on_interrupt;
  sigemptyset(&action.sa_mask);
  action.sa_flags = 0;  // no SA_RESTART: a blocking wait returns EINTR and polls
  for (int i = 0; i < 2; ++i) sigaction(kSignals[i], &action, &g_previous[i]);
}

InterruptHandlers::~InterruptHandlers() {
  for (int i = 0; i < 2; ++i) sigaction(kSignals[i], &g_previous[i], nullptr);
}

void end_as_signalled() {
  const int sig = interrupt_signal();
  if (sig == 0) return;
  std::cout.flush();
  std::fflush(nullptr);
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

}  // namespace shockgas::app
