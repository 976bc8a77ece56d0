#include "child_process.hpp"

#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <thread>

#include "fault.hpp"
#include "shockgas/core/interrupt.hpp"

namespace shockgas::app {

namespace {

using namespace std::chrono_literals;
constexpr auto kPoll = 20ms;   // how soon an interrupt reaches the child
constexpr auto kGrace = 2s;    // SIGTERM, then SIGKILL after this

int status_code(int status) {
  return WIFEXITED(status) ? WEXITSTATUS(status) : WIFSIGNALED(status) ? 128 + WTERMSIG(status) : 1;
}

// In the child, between fork and exec: async-signal-safe calls only.
[[noreturn]] void exec_child(char* const* argv, pid_t parent) {
  setpgid(0, 0);
  prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (getppid() != parent) _exit(127);  // the parent died before prctl
  signal(SIGINT, SIG_DFL);
  signal(SIGTERM, SIG_DFL);
  execv(argv[0], argv);
  _exit(127);
}

// Waits for the child; false if an interrupt came first.
bool wait_polling(pid_t child, int& status) {
  for (;;) {
    const pid_t done = waitpid(child, &status, WNOHANG);
    if (done == child || (done < 0 && errno != EINTR)) return true;
    if (interrupt_requested() == InterruptMode::abort) return false;
    fault_point("plot");
    std::this_thread::sleep_for(kPoll);
  }
}

void stop(pid_t child, int& status) {
  kill(-child, SIGTERM);
  const auto deadline = std::chrono::steady_clock::now() + kGrace;
  while (waitpid(child, &status, WNOHANG) == 0) {
    if (std::chrono::steady_clock::now() > deadline) {
      kill(-child, SIGKILL);
      waitpid(child, &status, 0);
      return;
    }
    std::this_thread::sleep_for(kPoll);
  }
}

}  // namespace

int run_child(const std::vector<std::string>& args) {
  std::vector<char*> argv;
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  const pid_t parent = getpid();
  const pid_t child = fork();
  if (child < 0) return 127;
  if (child == 0) exec_child(argv.data(), parent);
  setpgid(child, child);  // also here: no race with a kill of the group
  int status = 0;
  if (wait_polling(child, status)) return status_code(status);
  stop(child, status);
  throw_if_aborted();
  return status_code(status);
}

}  // namespace shockgas::app
