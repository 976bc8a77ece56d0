#pragma once
// Work that may crash this process, done in a child process instead: a
// library reading a file that may be damaged (the HDF5 library, which can
// crash inside a hostile file) only ever takes the child down.
//
// run_isolated forks; the child runs work(send), each send(bytes) streamed to
// the parent through a pipe and handed to receive(bytes) as it arrives, then
// ends. The child ignores SIGINT, SIGTERM and SIGHUP (the parent decides) and
// dies with the parent (PR_SET_PDEATHSIG); its address space is limited to
// what it holds at the fork plus `memory` bytes, so that a file that claims
// more data than it holds cannot take the machine's memory. The parent polls
// core/interrupt.hpp while it waits: an interrupt request kills the child and
// throws Interrupted. Only the forking thread runs in the child: `held`, if
// given, is locked across the fork, so that no other thread is inside the
// library the child uses at that moment.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <mutex>
#include <string>

namespace shockgas::app {

using Send = std::function<void(const char* data, std::size_t size)>;

// "" when the child ended normally (exit status 0), else why it did not:
// "killed by signal 11 (Segmentation fault)", "exit status 3", "silent for
// 10 s" (it sent nothing for `silence` seconds: taken as hung, an endless loop
// inside a damaged file, and killed). RunError if the child cannot be started.
std::string run_isolated(const std::function<void(const Send& send)>& work, const Send& receive,
                         std::uint64_t memory, double silence, std::recursive_mutex* held = nullptr);

}  // namespace shockgas::app
