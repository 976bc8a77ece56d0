#pragma once
#include <string>

namespace shockgas::app {

// Draws the PNG plots of a result directory with scripts/plot_result.py
// (Debian's /usr/bin/python3 with matplotlib and h5py). The plots read only
// the result files. A missing plotting tool is a warning on stderr, not an error.
void make_plots(const std::string& dir);

}  // namespace shockgas::app
