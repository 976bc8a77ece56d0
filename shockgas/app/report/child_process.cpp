#include "shockgas/app/report/child_process.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <thread>

#include "shockgas/app/files/fault.hpp"
#include "shockgas/core/interrupt.hpp"

namespace shockgas::app {

namespace {

using namespace std::chrono_literals;
constexpr auto kPoll = 20ms;  // how soon an interrupt reaches the child
constexpr auto kGrace = 2s;   // SIGTERM, then SIGKILL after this

int status_code(int status) {
  return WIFEXITED(status) ? WEXITSTATUS(status) : WIFSIGNALED(status) ? 128 + WTERMSIG(status) : 1;
}

// In the child, between fork and exec: async-signal-safe calls only.
// err: the write end of the pipe that takes its stdout and stderr, or -1.
// Its stdin is /dev/null: in a group of its own it is in the background of a
// terminal, where a read (ffmpeg's, of keys) would stop it with SIGTTIN.
[[noreturn]] void exec_child(char* const* argv, pid_t parent, int err) {
  const int nothing = open("/dev/null", O_RDONLY);
  if (nothing < 0 || dup2(nothing, STDIN_FILENO) < 0) _exit(127);
  if (nothing != STDIN_FILENO) close(nothing);
  if (err >= 0 && (dup2(err, STDOUT_FILENO) < 0 || dup2(err, STDERR_FILENO) < 0)) _exit(127);
  setpgid(0, 0);
  prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (getppid() != parent) _exit(127);  // the parent died before prctl
  signal(SIGINT, SIG_DFL);
  signal(SIGTERM, SIG_DFL);
  signal(SIGPIPE, SIG_DFL);  // ignored by the command (signals.hpp), not by what it starts
  execv(argv[0], argv);
  _exit(127);
}

// The read end of the pipe that takes the child's stdout and stderr: read as it comes,
// so that the child never blocks on a full pipe; the last kSaidBytes kept.
class Said {
 public:
  Said(int fd, std::string* into) : fd_(fd), into_(into) {}
  ~Said() {
    if (fd_ >= 0) ::close(fd_);
  }
  Said(const Said&) = delete;
  Said& operator=(const Said&) = delete;

  // Waits up to kPoll for more, and reads what there is.
  void wait_and_read() {
    if (fd_ < 0 || !open_) {
      std::this_thread::sleep_for(kPoll);
      return;
    }
    pollfd p{fd_, POLLIN, 0};
    if (::poll(&p, 1, static_cast<int>(kPoll.count())) > 0) read_now();
  }
  // Reads what is there without waiting (the child may have left a descendant
  // holding the pipe open: its end is not waited for).
  void read_now() {
    char buf[4096];
    for (;;) {
      const ssize_t n = ::read(fd_, buf, sizeof buf);
      if (n > 0) {
        into_->append(buf, static_cast<std::size_t>(n));
        if (into_->size() > kSaidBytes) into_->erase(0, into_->size() - kSaidBytes);
        continue;
      }
      if (n < 0 && errno == EINTR) continue;
      if (n == 0) open_ = false;  // end of file: nothing more will come
      return;
    }
  }
  bool active() const { return fd_ >= 0; }

 private:
  int fd_;
  std::string* into_;
  bool open_ = true;
};

// Waits for the child; false if an interrupt came first.
bool wait_polling(pid_t child, int& status, Said& said) {
  for (;;) {
    const pid_t done = waitpid(child, &status, WNOHANG);
    if (done == child || (done < 0 && errno != EINTR)) {
      if (said.active()) said.read_now();
      return true;
    }
    if (interrupt_requested() == InterruptMode::abort) return false;
    fault_point("plot");
    said.wait_and_read();
  }
}

// SIGTERM to the child's group, SIGKILL after kGrace; then SIGKILL to what is
// left of the group (a process it started, such as an encoder still flushing
// its file), so that nothing writes after the command has stopped.
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
  kill(-child, SIGKILL);
}

}  // namespace

int run_child(const std::vector<std::string>& args, std::string* said) {
  std::vector<char*> argv;
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  int pipe_fds[2] = {-1, -1};
  if (said && ::pipe2(pipe_fds, O_CLOEXEC) != 0) return 127;
  Said reader(pipe_fds[0], said);
  const pid_t parent = getpid();
  const pid_t child = fork();
  if (child < 0) {
    if (pipe_fds[1] >= 0) ::close(pipe_fds[1]);
    return 127;
  }
  if (child == 0) exec_child(argv.data(), parent, pipe_fds[1]);
  if (pipe_fds[1] >= 0) {
    ::close(pipe_fds[1]);  // the child's copy alone: its end is the end of file
    ::fcntl(pipe_fds[0], F_SETFL, O_NONBLOCK);
  }
  setpgid(child, child);  // also here: no race with a kill of the group
  int status = 0;
  if (wait_polling(child, status, reader)) return status_code(status);
  stop(child, status);
  throw_if_aborted();
  return status_code(status);
}

}  // namespace shockgas::app
