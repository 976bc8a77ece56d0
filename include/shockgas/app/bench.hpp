#pragma once
// `shockgas bench`: work-precision charts and stability maps of every method
// (docs/performance.md). Writes CSV files and PNG charts into out_dir.
#include <string>

namespace shockgas::app {

struct BenchOptions {
  std::string out_dir = "out/bench";  // where the CSV and PNG files go
  bool full = false;                  // the record size (minutes to hours) instead of the quick one
  bool progress = true;               // progress lines on stderr
};

// Returns the output directory. Throws InputError for bad options, RunError on failure.
std::string run_bench(const BenchOptions& options);

}  // namespace shockgas::app
