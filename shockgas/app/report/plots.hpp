#pragma once
#include <filesystem>
#include <string>
#include <vector>

namespace shockgas::app {

// The folder of the drawing scripts: data_dir()/plots (shockgas/app/files/data_dir.hpp),
// empty where there is none. The one place the command looks them up.
std::filesystem::path plots_dir();

// Runs plots_dir()/<script> DIR with Debian's /usr/bin/python3 (matplotlib, h5py);
// env_override names an environment variable that may give another script path.
// Returns what to tell the user on stderr, whole lines (empty: nothing):
// - when the script ran to its end, what it said there (its own warnings);
// - else one warning naming `what` and the reason: python, the script or a
//   plotting library missing, or the script failed (the reason: the last line
//   it said). The result files are complete without the pictures; a failed
//   script's messages (a Python traceback) are kept in DIR/<log> instead, and the
//   pictures it left half-written (DIR/*.partial) are removed.
// within: DIR as the user finds it in the output directory, for the message
// ("": the output directory itself; a sweep's variant: its subdirectory).
// Throws RunError when the pictures could not be written: the script's exit 4
// (its last line "cannot write PATH: REASON"), or any failure that leaves no
// room on DIR's file system. A directory that cannot take them cannot take the
// run's other files either, and a run that fails says so once.
// args: more arguments after DIR.
std::string run_plot_script(const std::string& script, const char* env_override, const std::string& dir,
                            const std::string& what, const std::string& log, const std::string& within = "",
                            const std::vector<std::string>& args = {});

// The PNG plots of a result directory (plots/plot_result.py), read only from
// its result files, and with `animation` its animation, by the same process (its
// imports paid once, the animation drawn beside the pictures); a failed
// script's messages in plots.log.
std::string make_plots(const std::string& dir, bool animation, const std::string& within = "");

// The animation of a result directory alone (plots/animate.py, `shockgas
// animate`), from its result.h5; a failed script's messages in animation.log.
// args: the script's options (--fps N, --size WxH, --frames N), checked by the caller.
std::string make_animation(const std::string& dir, const std::string& within = "",
                           const std::vector<std::string>& args = {});

// The charts of `shockgas bench` (plots/plot_bench.py), read only from the CSV
// files of the studies in dir; a failed script's messages in charts.log.
std::string make_bench_charts(const std::string& dir);

}  // namespace shockgas::app
