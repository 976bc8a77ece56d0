#include "plots.hpp"

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <iostream>

namespace shockgas::app {

namespace {

std::string quoted(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

std::string plot_script() {
  if (const char* env = std::getenv("SHOCKGAS_PLOT_SCRIPT")) return env;
  return std::string(SHOCKGAS_SOURCE_DIR) + "/scripts/plot_result.py";
}

}  // namespace

void make_plots(const std::string& dir) {
  const std::string python = "/usr/bin/python3", script = plot_script();
  if (!std::filesystem::exists(python) || !std::filesystem::exists(script)) {
    std::cerr << "shockgas: warning: no plots (" << (std::filesystem::exists(python) ? script : python)
              << " not found; run scripts/setup)\n";
    return;
  }
  const std::string cmd = python + " " + quoted(script) + " " + quoted(dir);
  const int status = std::system(cmd.c_str());
  const int code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  if (code == 3)
    std::cerr << "shockgas: warning: no plots (matplotlib or h5py missing for /usr/bin/python3; run scripts/setup)\n";
  else if (code != 0)
    std::cerr << "shockgas: warning: plotting failed (exit " << code << "); the results are complete\n";
}

}  // namespace shockgas::app
