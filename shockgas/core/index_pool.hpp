#pragma once
// Independent jobs 0..n-1 (realizations) on a few threads.
//
// Contract: work(k) runs once for every k < n unless a job throws; indices are
// handed out in increasing order to whichever thread is free, so a job must not
// depend on which thread runs it or on the order the jobs finish (results go to
// slot k, or are combined in index order afterwards). The calling thread is one
// of the `threads`. The first exception stops the handing out of further
// indices; the jobs already running finish, and that exception is rethrown once
// every thread has joined.
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

#include "shockgas/core/thread_start.hpp"

namespace shockgas {

template <class Work>
void run_indices(std::size_t n, std::size_t threads, Work&& work) {
  std::atomic<std::size_t> next{0};
  std::exception_ptr error;
  std::mutex error_mutex;
  auto worker = [&] {
    for (std::size_t k = next++; k < n; k = next++) {
      try {
        work(k);
      } catch (...) {
        const std::lock_guard<std::mutex> lock(error_mutex);
        if (!error) error = std::current_exception();
        next = n;
      }
    }
  };
  const std::size_t team = std::max<std::size_t>(1, std::min(threads, n));
  std::vector<std::thread> pool;
  pool.reserve(team - 1);
  // The threads wait until all are started: a thread the system refuses stops
  // the pool before any job runs (thread_start.hpp).
  std::atomic<bool> go{false};
  const auto member = [&] {
    go.wait(false);
    worker();
  };
  try {
    for (std::size_t i = 1; i < team; ++i) pool.push_back(start_thread(member));
  } catch (...) {
    next = n;
    go = true;
    go.notify_all();
    for (std::thread& th : pool) th.join();
    throw;
  }
  go = true;
  go.notify_all();
  worker();
  for (std::thread& th : pool) th.join();
  if (error) std::rethrow_exception(error);
}

}  // namespace shockgas
