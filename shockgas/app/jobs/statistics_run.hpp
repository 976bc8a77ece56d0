#pragma once
// `shockgas stats DIR... [--out DIR]`: the shock statistics of one gas over
// every realization the directories hold (runs, merged runs, shards; several
// seeds are independent samples), computed by compare::shock_statistics and
// written as statistics.h5, statistics.csv, statistics.md and statistics.png
// into a directory of its own, whole or absent (run_directory.hpp).
//
// The sources must be of one gas (gas_of: InputError naming the first key that
// differs) and hold each realization once (the same seed and realization index
// twice is refused, naming both directories). Realizations that stopped before
// t_end (collapse, a limit) are left out and counted.
#include <string>
#include <vector>

namespace shockgas::app {

struct StatisticsOptions {
  std::vector<std::string> dirs;
  std::string out_dir;  // "" = out/<scene>-stats
  bool force = false;   // replace a directory of another scene's results
  bool plots = true;
  bool quiet = false;
};

// Returns the output directory. What it found is printed on stdout (the
// numbers of statistics.md) unless quiet.
std::string run_statistics(const StatisticsOptions& options);

}  // namespace shockgas::app
