#pragma once
// The method studies behind docs/performance.md: work-precision charts and
// stability maps of every continuum solver and of the particle engine. Each
// study writes CSV files into the output directory; `shockgas bench` runs them
// and then draws the charts from those files (plots/plot_bench.py).
#include <string>

namespace shockgas::studies {

struct StudyOptions {
  std::string out_dir = "out/bench";  // where the CSV files go
  bool full = false;                  // the record size (minutes to hours) instead of the quick one
  bool progress = true;               // progress lines on stderr
};

// Runs every study (or those named in SHOCKGAS_BENCH_SECTIONS, comma-separated)
// and writes their CSV files and the failure table (failures.csv, failures.md).
// Returns the output directory. Throws InputError for bad options, RunError on failure.
std::string run_studies(const StudyOptions& options);

// Whether run_studies runs every section (SHOCKGAS_BENCH_SECTIONS unset, empty
// or naming all four); InputError if it names something that is not a section.
bool runs_every_section();

}  // namespace shockgas::studies
