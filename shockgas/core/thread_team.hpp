#pragma once
// A fixed team of threads for the stages of one computation (the time windows
// of a realization, particles/window_scheduler.hpp; the steps of a
// finite-volume grid, continuum/godunov_scheme.hpp): run(job) calls job(k)
// once on each member k = 0 .. size() - 1 (member 0 is the calling thread) and
// returns when all have finished. The members wait between stages, so a stage
// costs no thread creation. What a stage computes must not depend on which
// member does which part (the callers claim work by index).
//
// A member that has finished waits for the next stage (and the caller for the
// members) by spinning for up to kSpins pauses (tens of microseconds) before it
// sleeps on a condition variable: stages that follow each other closely (a
// grid's steps of 0.1-0.2 ms) would otherwise pay a sleep and a wake-up each,
// as long as the stage itself.
#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

#include "shockgas/core/thread_start.hpp"

namespace shockgas {

class ThreadTeam {
 public:
  // RunError (core/thread_start.hpp) if the system refuses a member: those
  // started are joined first.
  explicit ThreadTeam(std::size_t size) {
    try {
      for (std::size_t k = 1; k < size; ++k) members_.push_back(start_thread([this, k] { serve(k); }));
    } catch (...) {
      close();
      throw;
    }
  }
  ThreadTeam(const ThreadTeam&) = delete;
  ThreadTeam& operator=(const ThreadTeam&) = delete;
  ~ThreadTeam() { close(); }

  std::size_t size() const { return members_.size() + 1; }

  // Runs job(k) on every member; rethrows the first exception any member threw.
  void run(const std::function<void(std::size_t)>& job) {
    if (members_.empty()) return job(0);
    {
      std::lock_guard lock(mutex_);
      job_ = &job;
      pending_ = members_.size();
      error_ = nullptr;
      stage_.fetch_add(1, std::memory_order_release);
    }
    wake_.notify_all();
    call(job, 0);
    spin([this] { return pending_.load(std::memory_order_acquire) == 0; });
    std::unique_lock lock(mutex_);
    done_.wait(lock, [this] { return pending_ == 0; });
    job_ = nullptr;
    if (error_) std::rethrow_exception(error_);
  }

  // Pauses of a wait's spin before it sleeps (about 30-60 us).
  static constexpr int kSpins = 2000;

 private:
  void call(const std::function<void(std::size_t)>& job, std::size_t k) {
    try {
      job(k);
    } catch (...) {
      std::lock_guard lock(mutex_);
      if (!error_) error_ = std::current_exception();
    }
  }
  void close() {
    {
      std::lock_guard lock(mutex_);
      closing_ = true;
    }
    wake_.notify_all();
    for (std::thread& t : members_) t.join();
    members_.clear();
  }
  // Spins until done() or kSpins pauses have passed.
  template <class Done>
  static void spin(const Done& done) {
    for (int k = 0; k < kSpins && !done(); ++k) {
#if defined(__x86_64__) || defined(__i386__)
      __builtin_ia32_pause();
#endif
    }
  }
  void serve(std::size_t k) {
    std::size_t seen = 0;
    for (;;) {
      const std::function<void(std::size_t)>* job = nullptr;
      spin([&] { return stage_.load(std::memory_order_acquire) != seen || closing_.load(); });
      {
        std::unique_lock lock(mutex_);
        wake_.wait(lock, [&] { return closing_ || stage_ != seen; });
        if (closing_) return;
        seen = stage_;
        job = job_;
      }
      call(*job, k);
      std::lock_guard lock(mutex_);
      if (--pending_ == 0) done_.notify_one();
    }
  }

  std::vector<std::thread> members_;
  std::mutex mutex_;
  std::condition_variable wake_, done_;
  const std::function<void(std::size_t)>* job_ = nullptr;
  std::atomic<std::size_t> stage_ = 0, pending_ = 0;  // written under mutex_, read by the spins too
  std::exception_ptr error_;
  std::atomic<bool> closing_ = false;
};

}  // namespace shockgas
