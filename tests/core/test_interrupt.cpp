#include <gtest/gtest.h>

#include <csignal>
#include <thread>

#include "shockgas/core/interrupt.hpp"

namespace shockgas {
namespace {

class InterruptTest : public ::testing::Test {
 protected:
  void SetUp() override { clear_interrupt(); }
  void TearDown() override { clear_interrupt(); }
};

TEST_F(InterruptTest, NothingPendingAtStart) {
  EXPECT_EQ(interrupt_requested(), InterruptMode::none);
  EXPECT_EQ(interrupt_signal(), 0);
  EXPECT_NO_THROW(throw_if_aborted());
}

TEST_F(InterruptTest, AbortWinsOverCheckpointAndIsNeverWeakened) {
  request_interrupt(InterruptMode::checkpoint, SIGTERM);
  EXPECT_EQ(interrupt_requested(), InterruptMode::checkpoint);
  EXPECT_NO_THROW(throw_if_aborted());  // a checkpoint request is the caller's to honour
  request_interrupt(InterruptMode::abort, SIGINT);
  EXPECT_EQ(interrupt_requested(), InterruptMode::abort);
  request_interrupt(InterruptMode::checkpoint, SIGTERM);
  EXPECT_EQ(interrupt_requested(), InterruptMode::abort);
  EXPECT_EQ(interrupt_signal(), SIGTERM);  // the last signal is the one reported
}

TEST_F(InterruptTest, AbortThrowsInterruptedCarryingTheSignal) {
  request_interrupt(InterruptMode::abort, SIGINT);
  try {
    throw_if_aborted();
    FAIL() << "no Interrupted thrown";
  } catch (const Interrupted& e) {
    EXPECT_EQ(e.signal_number(), SIGINT);
  }
}

TEST_F(InterruptTest, RequestFromASignalHandlerIsSeenByAnotherThread) {
  std::signal(SIGUSR1, [](int sig) { request_interrupt(InterruptMode::abort, sig); });
  std::raise(SIGUSR1);
  std::signal(SIGUSR1, SIG_DFL);
  InterruptMode seen = InterruptMode::none;
  std::thread reader([&] { seen = interrupt_requested(); });
  reader.join();
  EXPECT_EQ(seen, InterruptMode::abort);
  EXPECT_EQ(interrupt_signal(), SIGUSR1);
}

}  // namespace
}  // namespace shockgas
