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
  for (std::size_t i = 1; i < team; ++i) pool.emplace_back(worker);
  worker();
  for (std::thread& th : pool) th.join();
  if (error) std::rethrow_exception(error);
}

}  // namespace shockgas
