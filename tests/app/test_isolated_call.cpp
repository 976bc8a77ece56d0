// run_isolated (shockgas/app/files/isolated_call.hpp): a child that goes
// silent past its bound is killed and said to be so; one that keeps talking
// is not, however long it runs; a crash is reported, not suffered.
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <string>
#include <thread>

#include "shockgas/app/files/isolated_call.hpp"

namespace shockgas::app {
namespace {

using namespace std::chrono_literals;

constexpr std::uint64_t kMemory = 64u << 20;

// What a damaged file made the HDF5 library do: loop without end, sending nothing.
TEST(IsolatedCall, AChildSilentPastItsBoundIsKilledAndSaidToBe) {
  std::string received;
  const std::string ended = run_isolated(
      [](const Send& send) {
        send("a", 1);
        for (volatile bool forever = true; forever;) {
        }
      },
      [&](const char* data, std::size_t size) { received.append(data, size); }, kMemory, 0.5);
  EXPECT_EQ(ended, "silent for 0.5 s");
  EXPECT_EQ(received, "a");
}

// 1.2 s of work in pieces 0.1 s apart, with a bound of 0.5 s: the silence is
// counted from the last piece, not from the start.
TEST(IsolatedCall, AChildThatKeepsSendingRunsPastTheBound) {
  std::string received;
  const std::string ended = run_isolated(
      [](const Send& send) {
        for (int k = 0; k < 12; ++k) {
          std::this_thread::sleep_for(100ms);
          send("x", 1);
        }
      },
      [&](const char* data, std::size_t size) { received.append(data, size); }, kMemory, 0.5);
  EXPECT_EQ(ended, "");
  EXPECT_EQ(received, std::string(12, 'x'));
}

// SIGKILL, which no sanitizer's handler catches, as the end of a crash.
TEST(IsolatedCall, AChildKilledBySignalIsReportedByIt) {
  const std::string ended = run_isolated([](const Send&) { ::kill(::getpid(), SIGKILL); },
                                         [](const char*, std::size_t) {}, kMemory, 10);
  EXPECT_EQ(ended.rfind("killed by signal 9", 0), 0u) << ended;
}

}  // namespace
}  // namespace shockgas::app
