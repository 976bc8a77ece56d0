#include "plots.hpp"

#include <cstdlib>
#include <filesystem>
#include <iostream>

#include "child_process.hpp"

namespace shockgas::app {

void run_plot_script(const std::string& script, const char* env_override, const std::string& dir,
                     const std::string& what) {
  const char* env = env_override ? std::getenv(env_override) : nullptr;
  const std::string python = "/usr/bin/python3",
                    path = env ? env : std::string(SHOCKGAS_SOURCE_DIR) + "/scripts/" + script;
  if (!std::filesystem::exists(python) || !std::filesystem::exists(path)) {
    std::cerr << "shockgas: warning: no " << what << " (" << (std::filesystem::exists(python) ? path : python)
              << " not found; run scripts/setup)\n";
    return;
  }
  const int code = run_child({python, path, dir});  // Interrupted on SIGINT, SIGTERM
  if (code == 3)
    std::cerr << "shockgas: warning: no " << what
              << " (matplotlib or h5py missing for /usr/bin/python3; run scripts/setup)\n";
  else if (code != 0)
    std::cerr << "shockgas: warning: " << what << " failed (exit " << code << "); the results are complete\n";
}

void make_plots(const std::string& dir) { run_plot_script("plot_result.py", "SHOCKGAS_PLOT_SCRIPT", dir, "plots"); }

void make_animation(const std::string& dir) {
  run_plot_script("animate.py", "SHOCKGAS_ANIMATE_SCRIPT", dir, "animation");
}

void make_bench_charts(const std::string& dir) {
  run_plot_script("plot_bench.py", "SHOCKGAS_PLOT_BENCH_SCRIPT", dir, "bench charts");
}

}  // namespace shockgas::app
