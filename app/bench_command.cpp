// `shockgas bench`: runs every section (bench_sections.hpp), writes the failure
// table, then draws the charts from the CSV files with scripts/plot_bench.py.
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <iostream>

#include "bench_sections.hpp"
#include "plots.hpp"
#include "shockgas/app/bench.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::app {

namespace {

// The charts read only the CSV files; a missing python or matplotlib is a warning.
void plot(const std::string& dir) { run_plot_script("plot_bench.py", "SHOCKGAS_PLOT_BENCH_SCRIPT", dir, "bench charts"); }

// SHOCKGAS_BENCH_SECTIONS (comma-separated section names) runs only those
// sections, for re-measuring one chart; unset runs them all.
bool selected(const std::string& section) {
  const char* env = std::getenv("SHOCKGAS_BENCH_SECTIONS");
  if (!env || !*env) return true;
  return ("," + std::string(env) + ",").find("," + section + ",") != std::string::npos;
}

}  // namespace

std::string run_bench(const BenchOptions& options) {
  if (options.out_dir.empty()) throw InputError("bench.out", "\"\"", "a directory name");
  std::error_code ec;
  std::filesystem::create_directories(options.out_dir, ec);
  if (ec || !std::filesystem::is_directory(options.out_dir))
    throw InputError("bench.out", to_text(options.out_dir), "a directory that can be created");
  bench::Context ctx{options.out_dir, options.full, options.progress};
  bench::FailureLog failures;
  const auto start = std::chrono::steady_clock::now();
  if (selected("continuum_wp")) bench::continuum_work_precision(ctx, failures);
  if (selected("continuum_stability")) bench::continuum_stability(ctx, failures);
  if (selected("particles_wp")) bench::particle_work_precision(ctx, failures);
  if (selected("particles_stability")) bench::particle_stability(ctx, failures);
  failures.write(ctx);
  ctx.log("done", std::to_string(failures.all().size()) + " failures detected (failures.md), " +
                      bench::fmt(bench::seconds_since(start)) + " s; drawing charts");
  plot(options.out_dir);
  return options.out_dir;
}

}  // namespace shockgas::app
