#include "shockgas/app/report/plots.hpp"

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <regex>

#include "shockgas/app/files/data_dir.hpp"
#include "shockgas/app/files/durable_file.hpp"
#include "shockgas/app/report/child_process.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::app {

namespace fs = std::filesystem;

namespace {

// The plotting scripts' exit codes (plots/plot_result.py): 3 a library is
// missing, 4 a picture could not be written.
constexpr int kMissingLibrary = 3, kCannotWrite = 4;

// The last line the script said, without its own name in front and, for an
// error of the system (Python's "OSError: [Errno 28] No space left on device"),
// the system's reason alone.
std::string reason_of(const std::string& said, const std::string& script) {
  const std::size_t end = said.find_last_not_of(" \n\r\t");
  if (end == std::string::npos) return "";
  const std::size_t newline = said.rfind('\n', end);
  const std::size_t begin = newline == std::string::npos ? 0 : newline + 1;
  std::string line = said.substr(begin, end + 1 - begin);
  if (line.rfind(script + ": ", 0) == 0) line.erase(0, script.size() + 2);
  static const std::regex system_error(R"(^[A-Za-z_][\w.]*: \[Errno \d+\] (.*)$)");
  std::smatch m;
  if (std::regex_match(line, m, system_error)) line = m[1].str();
  return line;
}

std::string ended_by_signal(int sig) {
  const char* abbrev = sigabbrev_np(sig);
  return "ended by signal " + std::to_string(sig) + (abbrev ? std::string(" (SIG") + abbrev + ")" : "");
}

// What a script that failed half-way through a picture left of it.
void remove_partial_pictures(const fs::path& dir) {
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dir, ec))
    if (entry.path().extension() == ".partial" && entry.is_regular_file(ec)) fs::remove(entry.path(), ec);
}

// The drawing scripts' folder under a data directory (data_dir.hpp).
fs::path plots_in(const fs::path& data) { return data / "plots"; }

}  // namespace

fs::path plots_dir() {
  const auto data = data_dir();
  return data ? plots_in(*data) : fs::path();
}

std::string run_plot_script(const std::string& script, const char* env_override, const std::string& dir,
                            const std::string& what, const std::string& log, const std::string& within,
                            const std::vector<std::string>& args) {
  const char* env = env_override ? std::getenv(env_override) : nullptr;
  std::string tried;
  const auto data = data_dir(&tried);  // looked up once: the warning names where
  if (!env && !data)
    return "shockgas: warning: no " + what + " (the plotting package is in none of " + tried +
           "; set SHOCKGAS_DATA_DIR to the folder holding plots/)\n";
  const std::string python = "/usr/bin/python3", path = env ? env : (plots_in(*data) / script).string();
  if (!fs::exists(python) || !fs::exists(path))
    return "shockgas: warning: no " + what + " (" + (fs::exists(python) ? path : python) +
           " not found; run scripts/setup)\n";
  std::string said;
  int code = 0;
  std::vector<std::string> command{python, path, dir};
  command.insert(command.end(), args.begin(), args.end());
  try {
    code = run_child(command, &said);  // Interrupted on SIGINT, SIGTERM
  } catch (...) {  // stopped: a finished directory (animate) keeps no half-written picture
    remove_partial_pictures(dir);
    throw;
  }
  if (code == 0) {
    std::error_code ec;
    fs::remove(fs::path(dir) / log, ec);  // an earlier failure's log (animate DIR again) no longer holds
    return said;
  }
  const std::string name = fs::path(path).filename().string();
  const std::string reason = code > 128 ? ended_by_signal(code - 128) : reason_of(said, name);
  if (code == kMissingLibrary)
    return "shockgas: warning: no " + what + " (matplotlib or h5py missing for /usr/bin/python3" +
           (reason.empty() ? "" : ": " + reason) + "; run scripts/setup)\n";
  const bool no_room = free_bytes(dir) == 0;  // before the half-written pictures go
  remove_partial_pictures(dir);
  if (code == kCannotWrite && reason.rfind("cannot write ", 0) == 0) throw RunError(reason + room_note(dir));
  if (code == kCannotWrite || no_room)
    throw RunError("cannot write the " + what + " into " + dir + ": " +
                   (reason.empty() ? name + " ended with exit " + std::to_string(code) : reason) +
                   room_note(dir));
  const std::string failed = "shockgas: warning: " + what + " failed" +
                             (reason.empty() ? "" : ": " + reason) + " (" + name + ", exit " +
                             std::to_string(code);
  if (said.empty()) return failed + ")\n";
  const bool cut = said.size() >= kSaidBytes;  // run_child keeps the last kSaidBytes
  write_file(fs::path(dir) / log, (cut ? "[" + name + " said more: only its last " +
                                             std::to_string(kSaidBytes / 1024) + " kB are kept here]\n"
                                       : std::string()) +
                                      said);
  return failed + "; its messages are kept in " + (within.empty() ? log : within + "/" + log) + ")\n";
}

std::string make_plots(const std::string& dir, bool animation, const std::string& within) {
  if (!animation)
    return run_plot_script("plot_result.py", "SHOCKGAS_PLOT_SCRIPT", dir, "plots", "plots.log", within);
  return run_plot_script("plot_result.py", "SHOCKGAS_PLOT_SCRIPT", dir, "plots and animation", "plots.log",
                         within, {"--animation"});
}

std::string make_animation(const std::string& dir, const std::string& within,
                           const std::vector<std::string>& args) {
  return run_plot_script("animate.py", "SHOCKGAS_ANIMATE_SCRIPT", dir, "animation", "animation.log", within,
                         args);
}

std::string make_bench_charts(const std::string& dir) {
  return run_plot_script("plot_bench.py", "SHOCKGAS_PLOT_BENCH_SCRIPT", dir, "bench charts", "charts.log");
}

}  // namespace shockgas::app
