#pragma once
#include <string>

namespace shockgas::app {

// Runs scripts/<script> DIR with Debian's /usr/bin/python3 (matplotlib, h5py);
// env_override names an environment variable that may give another script path.
// A missing python, script or plotting library is a warning on stderr naming
// `what`, never an error: the result files are complete without the pictures.
void run_plot_script(const std::string& script, const char* env_override, const std::string& dir,
                     const std::string& what);

// The PNG plots of a result directory (scripts/plot_result.py), read only from
// its result files.
void make_plots(const std::string& dir);

// The animation of a result directory (scripts/animate.py), from its result.h5.
void make_animation(const std::string& dir);

// The charts of `shockgas bench` (scripts/plot_bench.py), read only from the CSV
// files of the studies in dir.
void make_bench_charts(const std::string& dir);

}  // namespace shockgas::app
