#include "shockgas/app/files/isolated_call.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <fstream>
#include <new>

#include "shockgas/core/error.hpp"
#include "shockgas/core/interrupt.hpp"

namespace shockgas::app {

namespace {

// The address space of this process now (VmSize) [bytes]; 0 if unknown.
std::uint64_t address_space() {
  std::ifstream in("/proc/self/statm");
  std::uint64_t pages = 0;
  in >> pages;
  return pages * static_cast<std::uint64_t>(::sysconf(_SC_PAGESIZE));
}

void write_fully(int fd, const char* data, std::size_t size) {
  while (size > 0) {
    const ssize_t n = ::write(fd, data, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) _exit(4);  // the parent is gone
    data += n;
    size -= static_cast<std::size_t>(n);
  }
}

// The child: never returns. Exit 0 when work returned, 3 when it threw.
[[noreturn]] void child(int fd, const std::function<void(const Send&)>& work, std::uint64_t memory) {
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);
  for (const int sig : {SIGINT, SIGTERM, SIGHUP}) std::signal(sig, SIG_IGN);
  std::signal(SIGPIPE, SIG_DFL);
  if (const std::uint64_t now = address_space(); now > 0) {
    const rlimit limit{now + memory, now + memory};
    ::setrlimit(RLIMIT_AS, &limit);
  }
  try {
    work([fd](const char* data, std::size_t size) { write_fully(fd, data, size); });
  } catch (...) {
    _exit(3);
  }
  _exit(0);
}

std::string how_it_ended(int status) {
  if (WIFSIGNALED(status))
    return "killed by signal " + std::to_string(WTERMSIG(status)) + " (" + strsignal(WTERMSIG(status)) + ")";
  if (WIFEXITED(status) && WEXITSTATUS(status) != 0)
    return "exit status " + std::to_string(WEXITSTATUS(status));
  return "";
}

// Reads the child's stream until it closes it; "" or why the wait ended
// early (the child was then killed).
std::string collect(int fd, pid_t pid, const Send& receive, double silence) {
  using Clock = std::chrono::steady_clock;
  auto heard = Clock::now();
  std::string block(1 << 16, '\0');
  for (pollfd p{fd, POLLIN, 0};;) {
    if (interrupt_requested() != InterruptMode::none) {
      ::kill(pid, SIGKILL);
      return "interrupted";
    }
    const int ready = ::poll(&p, 1, 100);
    if (ready < 0 && errno != EINTR) return std::string("poll: ") + std::strerror(errno);
    if (ready <= 0) {
      if (std::chrono::duration<double>(Clock::now() - heard).count() > silence) {
        ::kill(pid, SIGKILL);
        return "silent for " + to_text(silence, 3) + " s";
      }
      continue;
    }
    const ssize_t n = ::read(fd, block.data(), block.size());
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return "";
    heard = Clock::now();
    receive(block.data(), static_cast<std::size_t>(n));
  }
}

}  // namespace

std::string run_isolated(const std::function<void(const Send& send)>& work, const Send& receive,
                         std::uint64_t memory, double silence, std::recursive_mutex* held) {
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0)
    throw RunError(std::string("cannot start a reading process: ") + std::strerror(errno));
  if (held) held->lock();
  const pid_t pid = ::fork();
  const int error = errno;
  if (pid == 0) {
    // The forking thread alone runs here, and the lock it held belongs to a
    // thread of the parent: made anew for the child's own use.
    if (held) new (held) std::recursive_mutex;
    ::close(fds[0]);
    child(fds[1], work, memory);
  }
  if (held) held->unlock();
  ::close(fds[1]);
  if (pid < 0) {
    ::close(fds[0]);
    throw RunError(std::string("cannot start a reading process: ") + std::strerror(error));
  }
  std::string stopped;
  try {
    stopped = collect(fds[0], pid, receive, silence);
  } catch (...) {  // receive() refused what came: the child is not waited for
    ::kill(pid, SIGKILL);
    ::close(fds[0]);
    ::waitpid(pid, nullptr, 0);
    throw;
  }
  ::close(fds[0]);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (stopped == "interrupted") throw Interrupted(interrupt_signal());
  return stopped.empty() ? how_it_ended(status) : stopped;
}

}  // namespace shockgas::app
