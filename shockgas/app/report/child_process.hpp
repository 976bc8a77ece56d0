#pragma once
// A helper program run to its end, or stopped with the run: the plotting
// script. The child runs in a process group of its own (a Ctrl-C at the
// terminal reaches shockgas alone, which decides), dies with shockgas
// (PR_SET_PDEATHSIG: no orphan even after a SIGKILL), and is stopped when an
// interrupt is requested (shockgas/core/interrupt.hpp): SIGTERM to its group, SIGKILL
// after a grace time (and to whatever is left of the group once the child is
// gone), then Interrupted is thrown. Its stdin is /dev/null: it never stops on
// a read from the terminal it is in the background of.
#include <cstddef>
#include <string>
#include <vector>

namespace shockgas::app {

// Runs argv (argv[0]: the program's path), inheriting stdout and stderr, and
// returns its exit status (128 + signal if a signal ended it; 127 if it could
// not be started). Throws Interrupted once the child is gone if an interrupt was
// requested meanwhile. Passes the fault point "plot" at each poll (fault.hpp).
// With `said`, the child's stdout and stderr go there instead (its last
// kSaidBytes), for the caller to tell the user what matters of it.
inline constexpr std::size_t kSaidBytes = std::size_t{64} * 1024;
int run_child(const std::vector<std::string>& argv, std::string* said = nullptr);

}  // namespace shockgas::app
