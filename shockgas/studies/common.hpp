#pragma once
// Shared machinery of `shockgas bench` (docs/performance.md): where the files
// go, progress lines, CSV tables, medians of repeated timings, error norms of
// cell averages and the table of detected failures.
#include <chrono>
#include <cstddef>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "shockgas/core/error.hpp"

namespace shockgas::studies {

// The size of a bench run and where it writes.
struct Context {
  std::string out_dir;      // existing directory for the CSV and PNG files
  bool full = false;        // record size instead of the quick one
  bool progress = true;     // progress lines on stderr
  std::size_t repeats = 5;  // timed runs per setting; the median is reported (>= 5)

  // "bench: <section>: <text>" on stderr when progress is on.
  void log(const std::string& section, const std::string& text) const;
  std::string path(const std::string& file) const;  // out_dir/file
};

// A table that cannot be written (a full disk): it ends the bench, never a
// method's failure.
class TableWriteFailed : public RunError {
 public:
  using RunError::RunError;
};

// In a catch of std::exception around a method's run: rethrows what ends the
// bench rather than the method (an interruption, shockgas/core/interrupt.hpp, or
// TableWriteFailed), so that only the method's own failures are recorded.
void rethrow_if_bench_failure(const std::exception& e);

// A CSV file with a header row; numbers in shortest round-trip form, text
// quoted only if it holds a comma or a quote. Non-finite numbers are written as
// empty cells (never "nan"), so a reader sees "not applicable", not a result.
class CsvWriter {
 public:
  CsvWriter(const std::string& path, const std::vector<std::string>& columns);
  CsvWriter& operator<<(double value);
  CsvWriter& operator<<(const std::string& text);
  CsvWriter& operator<<(const char* text) { return *this << std::string(text); }
  void
  end_row();  // RunError if the row has the wrong number of cells; TableWriteFailed if it cannot be written

 private:
  void separator();
  std::ofstream out_;
  std::string path_;
  std::size_t columns_ = 0, cells_ = 0;
};

// One failure found by a scan: which method, which parameter, what happened.
struct Failure {
  std::string section;    // "cfl", "viscous_explicit", "hopf_cole_fft", "collapse", ...
  std::string method;     // e.g. "godunov2 (mc)"
  std::string parameter;  // e.g. "cfl = 1.1"
  std::string what;       // in words: "total variation grew 3.2x", "RunError: ..."
};

// Collects failures from every section; written as failures.csv and failures.md.
// failures.csv's first column names the bench section (run_studies.cpp) a
// failure was found in, so that a bench of some sections keeps the others'.
class FailureLog {
 public:
  void begin_section(std::string name) { section_ = std::move(name); }
  void add(Failure f) { failures_.push_back({section_, std::move(f)}); }
  std::size_t size() const { return failures_.size(); }
  void write(const Context& ctx) const;
  // The failures of an earlier failures.csv at path found in sections other
  // than `measured`, added as they were (none from a file without the column).
  void keep_earlier(const std::string& path, const std::vector<std::string>& measured);

 private:
  struct Found {
    std::string bench_section;
    Failure failure;
  };
  std::string section_;
  std::vector<Found> failures_;
};

// Wall-clock seconds of fn(), median over `runs` calls (>= 1).
double median_seconds(std::size_t runs, const std::function<void()>& fn);

// Seconds since `start`.
double seconds_since(std::chrono::steady_clock::time_point start);

// Error norms of cell averages a against the reference b (same size, cell width h):
// L1 = sum |a - b| h, Linf = max |a - b|.
struct Norms {
  double l1 = 0, linf = 0;
};
Norms error_norms(const std::vector<double>& a, const std::vector<double>& b, double h);

// Shock-position error from cell averages: where the profile v falls through
// v_mid (the mean of the shock's two sides, which for Burgers is the shock
// speed), interpolated linearly between cell centres, nearest to the exact shock
// x_s within half_width (periodic domain of `length`), against the same crossing
// of the exact cell averages (so that the exact solver scores 0). NaN if either
// profile has no such crossing in the window.
double shock_position_error(const std::vector<double>& v, const std::vector<double>& exact, double length,
                            double x_s, double v_mid, double half_width);

// Short text for numbers in messages ("1.5e-03").
std::string fmt(double value, int digits = 3);

// The names of the solvers the studies measure, as registered (shockgas/continuum/registry.hpp).
struct SolverNames {
  std::string godunov, godunov2, pressureless, hopf_lax, hopf_cole, cvode, arkode;
  std::string events;  // the particle engine (particles::ParticleSolver::events)
};
const SolverNames& solver_names();

}  // namespace shockgas::studies
