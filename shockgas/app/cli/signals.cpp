#include "shockgas/app/cli/signals.hpp"

#include <csignal>
#include <cstdio>
#include <iostream>

#include "shockgas/app/ensemble/checkpointer.hpp"
#include "shockgas/core/interrupt.hpp"

namespace shockgas::app {

namespace {

// SIGHUP (the terminal closed, a session ended) stops a run as SIGTERM does,
// with a checkpoint; unless it was ignored when the command started (nohup).
constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP};
constexpr int kCount = 3;
struct sigaction g_previous[kCount], g_pipe;

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
  for (int i = 0; i < kCount; ++i) {
    sigaction(kSignals[i], nullptr, &g_previous[i]);
    if (kSignals[i] == SIGHUP && g_previous[i].sa_handler == SIG_IGN) continue;  // nohup
    sigaction(kSignals[i], &action, nullptr);
  }
  // A reader of stderr that goes away (`shockgas run ... 2>&1 | head -1`) ends
  // no run: writes to it fail and are left unsaid.
  struct sigaction ignore {};
  ignore.sa_handler = SIG_IGN;
  sigaction(SIGPIPE, &ignore, &g_pipe);
}

InterruptHandlers::~InterruptHandlers() {
  for (int i = 0; i < kCount; ++i) sigaction(kSignals[i], &g_previous[i], nullptr);
  sigaction(SIGPIPE, &g_pipe, nullptr);
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
