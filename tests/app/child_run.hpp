#pragma once
// The command as a separate process, for the tests that must see how it ends
// (a signal, a crash, an exit code) or send it signals: build/shockgas, or the
// program named by SHOCKGAS_TEST_BINARY (to run a test against another build).
#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "process_temp_path.hpp"

namespace shockgas::app::testing {

inline std::string shockgas_binary() {
  const char* other = std::getenv("SHOCKGAS_TEST_BINARY");
  return other ? other : std::string(SHOCKGAS_BINARY_DIR) + "/shockgas";
}

struct Options {
  std::map<std::string, std::string> env;  // set in the child
  std::filesystem::path cwd;               // empty: the test's
  bool own_group = false;                  // a process group of its own (for a Ctrl-C to the group)
  std::function<void()> in_child;          // after fork, before exec (setrlimit, ...)
};

inline Options with_env(std::map<std::string, std::string> env) {
  Options o;
  o.env = std::move(env);
  return o;
}
inline Options in_dir(std::filesystem::path cwd) {
  Options o;
  o.cwd = std::move(cwd);
  return o;
}
inline Options in_own_group() {
  Options o;
  o.own_group = true;
  return o;
}

// A started child; its stderr goes to a file read by err().
class Child {
 public:
  Child(std::vector<std::string> args, const Options& o = {}) {
    err_ =
        shockgas::testing_support::process_temp_path("shockgas-child-", std::to_string(counter()++) + ".err");
    args.insert(args.begin(), shockgas_binary());
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    pid_ = fork();
    if (pid_ == 0) {
      if (o.own_group) setpgid(0, 0);
      if (!o.cwd.empty() && chdir(o.cwd.c_str()) != 0) _exit(126);
      for (const auto& [k, v] : o.env) setenv(k.c_str(), v.c_str(), 1);
      const int fd = open(err_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      dup2(fd, 2);
      const int null = open("/dev/null", O_WRONLY);
      dup2(null, 1);
      std::signal(SIGINT, SIG_DFL);
      std::signal(SIGTERM, SIG_DFL);
      if (o.in_child) o.in_child();
      execv(argv[0], argv.data());
      _exit(127);
    }
    if (o.own_group) setpgid(pid_, pid_);
  }
  ~Child() {
    if (!done_) {
      kill(pid_, SIGKILL);
      wait();
    }
    std::error_code ec;
    std::filesystem::remove(err_, ec);
  }
  pid_t pid() const { return pid_; }

  // Waits for the end; the status as a shell reports it: the exit code, or 128 + signal.
  int wait() {
    if (!done_) {
      int status = 0;
      rusage usage{};
      wait4(pid_, &status, 0, &usage);
      done_ = true;
      signal_ = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
      code_ = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + signal_;
      peak_kb_ = usage.ru_maxrss;
    }
    return code_;
  }
  int signal() const { return signal_; }            // the signal that ended it, 0 if it exited
  long peak_memory_kb() const { return peak_kb_; }  // ru_maxrss after wait()
  // Whether it stopped (SIGSTOP, as SHOCKGAS_FAULT=point:stop does) within the time.
  bool wait_stopped(std::chrono::seconds limit = std::chrono::seconds(120)) {
    const auto end = std::chrono::steady_clock::now() + limit;
    while (std::chrono::steady_clock::now() < end) {
      int status = 0;
      const pid_t r = waitpid(pid_, &status, WNOHANG | WUNTRACED);
      if (r == pid_ && WIFSTOPPED(status)) return true;
      if (r == pid_) {
        done_ = true;
        signal_ = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
        code_ = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + signal_;
        return false;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return false;
  }
  std::string err() const {
    std::ifstream in(err_);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }

 private:
  static int& counter() {
    static int n = 0;
    return n;
  }
  pid_t pid_ = -1;
  std::filesystem::path err_;
  bool done_ = false;
  int code_ = -1, signal_ = 0;
  long peak_kb_ = 0;
};

// Runs the command to its end: {status as a shell reports it, stderr}.
inline std::pair<int, std::string> run_child(const std::vector<std::string>& args, const Options& o = {}) {
  Child c(args, o);
  const int code = c.wait();
  return {code, c.err()};
}

// The children of pid (from /proc), e.g. the plotting process of a run.
inline std::vector<pid_t> children_of(pid_t pid) {
  std::vector<pid_t> out;
  std::ifstream in("/proc/" + std::to_string(pid) + "/task/" + std::to_string(pid) + "/children");
  for (pid_t c; in >> c;) out.push_back(c);
  return out;
}

// Whether pid runs (a zombie, dead and not yet reaped, does not).
inline bool process_alive(pid_t pid) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/stat");
  std::string line;
  if (!std::getline(in, line)) return false;
  const auto close = line.rfind(')');
  return close != std::string::npos && close + 2 < line.size() && line[close + 2] != 'Z';
}

}  // namespace shockgas::app::testing
