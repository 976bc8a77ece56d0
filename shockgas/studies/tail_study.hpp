#pragma once
// The tail of the scaled velocity distribution Phi(z) at sizes a scene cannot
// hold (`shockgas tail`): realizations are run one per thread and reduced at
// once to folded tail histograms (shockgas/compare/velocity_tail.hpp), so memory holds
// one realization's state per thread, whatever the number of realizations.
//
// r = 0 runs the exact sticky gas (shockgas/core/sticky_hull.hpp: no collisions, advanced
// from one time to the next); r > 0 the event engine with snapshots at the
// times, its clusters found with the default criteria. Realization k of size N
// is make_initial_bodies({N, seed}, k): uniform velocities on [-1, 1] on the
// lattice (white noise of intensity D = 1/3).
//
// Files in out_dir (docs/paper.md shows them):
//   tail_phi.csv      N, t, z, clusters, Phi with its jackknife error, the exact
//                     law's bin mean, the local exponent with its error, the
//                     same estimator on the exact bins and the law's own;
//   tail_windows.csv  the fitted exponent a (and the straight-line slope of
//                     ln(-ln Phi)) on windows [z_lo, z_hi], data and exact law;
//   tail_runs.csv     per (N, t): particles, clusters, reach, chi-square of Phi
//                     against the law, T t^(2/3), collisions and CPU seconds.
#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace shockgas::studies {

struct TailStudyOptions {
  std::string out_dir = "out/tail";
  std::vector<std::size_t> sizes = {10000000};  // N per realization
  std::size_t realizations = 100;               // per size
  std::vector<double> times = {1e3, 1e4, 1e5};  // increasing
  double r = 0;                                 // 0: the exact hull; > 0: the event engine
  double delta = 1e-2;                          // the engine's threshold (r > 0)
  std::uint64_t seed = 1999;
  double bin_width = 0.05;   // in |z|
  double z_max = 8;          // the histograms' range in |z|
  double min_clusters = 25;  // a bin counts while it holds this many clusters
  std::size_t threads = 0;   // realizations at once; 0 = every core
  bool progress = true;      // a line per finished realization on stderr
  // Called when a size's rows are in the files (and flushed): the command
  // publishes the files as they then are (shockgas/app/cli/tail_run.hpp).
  std::function<void()> size_written;
};

// The sizes a study takes (tail.N), and what a refusal says of them.
inline constexpr std::size_t kTailMinN = 100;
inline constexpr double kTailMaxN = 4e9;
std::string tail_sizes_allowed();

// The jackknife's groups: enough for an error known to ~7% (sqrt(1/(2 G))).
inline constexpr std::size_t kTailJackknifeGroups = 100;

// The files a study writes into its output directory.
inline constexpr std::array<const char*, 3> kTailFiles = {"tail_phi.csv", "tail_windows.csv",
                                                          "tail_runs.csv"};

// InputError naming the option for options the study cannot run.
void validate_tail_study(const TailStudyOptions& options);

// Runs the study and writes its files; returns out_dir. Throws InputError for
// bad options (naming the option), RunError if a run fails.
std::string run_tail_study(const TailStudyOptions& options);

}  // namespace shockgas::studies
