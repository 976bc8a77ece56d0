#pragma once
// A thread started, or a RunError that says why not: the system refuses a
// thread (std::system_error) when the processes and threads of a user are
// limited (ulimit -u) or the system has none left. Whoever starts several
// stops and joins those already started before it passes the error on, so that
// a refused thread ends the run cleanly, never leaving it waiting for a thread
// that does not exist.
#include <string>
#include <system_error>
#include <thread>
#include <utility>

#include "shockgas/core/error.hpp"

namespace shockgas {

template <class F>
std::thread start_thread(F&& f) {
  try {
    return std::thread(std::forward<F>(f));
  } catch (const std::system_error& e) {
    throw RunError(std::string("cannot start a thread: ") + e.code().message() +
                   " (the system refused it: the processes and threads of this user are limited, ulimit -u, "
                   "or the system has none left)");
  }
}

}  // namespace shockgas
