// Limits of the process are met before any work, or end the run cleanly
// (findings of a hostile pass: particles.threads had no bound, and 2^63 - 1
// took every process slot of the machine; a thread the system refused left the
// run waiting for ever, deaf to SIGTERM; `shockgas tail` allocated until the
// kernel killed it). The children here run under limits of their own
// (RLIMIT_NPROC as an unprivileged user, RLIMIT_AS), so that a failure of the
// test cannot take the machine's processes or memory.
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "child_run.hpp"
#include "run_dir_checks.hpp"

namespace shockgas::app {
namespace {

using namespace testing;

constexpr uid_t kNobody = 65534;

// The command as user nobody with at most `processes` processes and threads.
Options limited_user(rlim_t processes) {
  Options o;
  o.in_child = [processes] {
    const rlimit limit{processes, processes};
    setrlimit(RLIMIT_NPROC, &limit);
    if (setgid(kNobody) != 0 || setuid(kNobody) != 0) _exit(125);
  };
  return o;
}

// Waits for the child at most `limit`, then kills it; the status, or -1 if it
// had to be killed (it hung).
int wait_bounded(Child& child, std::chrono::seconds limit = std::chrono::seconds(300)) {
  const auto end = std::chrono::steady_clock::now() + limit;
  while (std::chrono::steady_clock::now() < end) {
    if (!process_alive(child.pid())) return child.wait();
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  kill(child.pid(), SIGKILL);
  child.wait();
  return -1;
}

fs::path shared_dir(const std::string& name) {
  fs::path root = fresh_dir(name);
  fs::permissions(root, fs::perms::all);  // for the unprivileged user
  write_text(root / "scene.toml",
             "[scene]\nname = \"threads\"\n[initial]\nN = 20000\n[particles]\nr = 0.5\n"
             "t_end = 50\nrealizations = 2\n[output]\nplots = false\n");
  return root;
}

// A thread count beyond the cores is refused before any work, naming the key
// and the bound; 0 (one per core) is the way to ask for all.
TEST(ProcessLimits, AThreadCountBeyondTheCoresIsRefusedBeforeAnyWork) {
  if (::geteuid() != 0)
    GTEST_SKIP() << "runs the command as user nobody under a process limit, which needs root";
  const fs::path root = shared_dir("limits-threads");
  for (const std::string threads : {"9223372036854775807", "100000"}) {
    Child child({"run", (root / "scene.toml").string(), "--out", (root / "out").string(), "-q", "--set",
                 "particles.threads=" + threads},
                limited_user(64));
    EXPECT_EQ(wait_bounded(child), 2) << child.err();
    EXPECT_NE(child.err().find("particles.threads = " + threads +
                               " is not allowed; allowed: 0 (one thread per core) "
                               "or at most "),
              std::string::npos)
        << child.err();
    EXPECT_FALSE(fs::exists(root / "out"));
  }
  Child tail({"tail", "--N", "1000", "--realizations", "4", "--times", "10", "--threads", "100000", "--out",
              (root / "tail").string(), "-q"},
             limited_user(64));
  EXPECT_EQ(wait_bounded(tail), 2) << tail.err();
  EXPECT_NE(tail.err().find("tail.threads"), std::string::npos) << tail.err();
}

// A thread the system refuses (a process limit) ends the run with a message
// (exit 1), the output directory as it was; it never waits for ever.
TEST(ProcessLimits, AThreadTheSystemRefusesEndsTheRunCleanly) {
  if (::geteuid() != 0)
    GTEST_SKIP() << "runs the command as user nobody under a process limit, which needs root";
  const fs::path root = shared_dir("limits-refused");
  Child child({"run", (root / "scene.toml").string(), "--out", (root / "out").string(), "-q", "--set",
               "particles.threads=8"},
              limited_user(3));
  EXPECT_EQ(wait_bounded(child), 1) << child.err();
  EXPECT_NE(child.err().find("cannot start a thread"), std::string::npos) << child.err();
  EXPECT_FALSE(fs::exists(root / "out"));
}

// `shockgas tail` estimates its memory before it allocates: a size or a count
// of realizations that cannot fit is refused naming its option (exit 2). The
// children run under ulimit -v, so a run that allocates anyway fails there;
// under AddressSanitizer, which reserves terabytes of address space and so
// cannot run under ulimit -v, its allocator refuses any block over 2 GiB instead.
TEST(ProcessLimits, TheTailEstimatesItsMemoryBeforeItAllocates) {
  const fs::path root = fresh_dir("limits-tail");
  Options limited;
#if defined(__SANITIZE_ADDRESS__)
  limited.env = {{"ASAN_OPTIONS", "max_allocation_size_mb=2048:allocator_may_return_null=0:detect_leaks=0"}};
#else
  limited.in_child = [] {
    const rlimit limit{rlim_t{2} << 30, rlim_t{2} << 30};
    setrlimit(RLIMIT_AS, &limit);
  };
#endif
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"--N", "1000", "--realizations", "1000000000", "--times", "10"}, "tail.realizations"},
      {{"--N", "4e9", "--realizations", "2", "--times", "10"}, "tail.N"}};
  for (const auto& [options, key] : cases) {
    std::vector<std::string> args = {"tail", "--out", (root / "tail").string(), "-q"};
    args.insert(args.end(), options.begin(), options.end());
    const auto [code, err] = run_child(args, limited);
    EXPECT_EQ(code, 2) << err;
    EXPECT_NE(err.find(key + " = "), std::string::npos) << err;
    EXPECT_NE(err.find("that fits in the memory available"), std::string::npos) << err;
    EXPECT_TRUE(leftovers(root / "tail").empty());
    EXPECT_FALSE(fs::exists(root / "tail"));
  }
}

}  // namespace
}  // namespace shockgas::app
