// The studies in order (sections.hpp), then the table of the failures they found.
#include <chrono>
#include <cstdlib>
#include <filesystem>

#include "sections.hpp"
#include "shockgas/core/error.hpp"
#include "shockgas/studies/studies.hpp"

namespace shockgas::studies {

namespace {

// SHOCKGAS_BENCH_SECTIONS (comma-separated section names) runs only those
// sections, for re-measuring one chart; unset runs them all.
bool selected(const std::string& section) {
  if (runs_every_section()) return true;
  return ("," + std::string(std::getenv("SHOCKGAS_BENCH_SECTIONS")) + ",").find("," + section + ",") !=
         std::string::npos;
}

}  // namespace

bool runs_every_section() {
  const char* env = std::getenv("SHOCKGAS_BENCH_SECTIONS");
  return !env || !*env;
}

std::string run_studies(const StudyOptions& options) {
  if (options.out_dir.empty()) throw InputError("bench.out", "\"\"", "a directory name");
  std::error_code ec;
  std::filesystem::create_directories(options.out_dir, ec);
  if (ec || !std::filesystem::is_directory(options.out_dir))
    throw InputError("bench.out", to_text(options.out_dir), "a directory that can be created");
  Context ctx{options.out_dir, options.full, options.progress};
  FailureLog failures;
  const auto start = std::chrono::steady_clock::now();
  if (selected("continuum_wp")) continuum_work_precision(ctx, failures);
  if (selected("continuum_stability")) continuum_stability(ctx, failures);
  if (selected("particles_wp")) particle_work_precision(ctx, failures);
  if (selected("particles_stability")) particle_stability(ctx, failures);
  failures.write(ctx);
  ctx.log("done", std::to_string(failures.all().size()) + " failures detected (failures.md), " +
                      fmt(seconds_since(start)) + " s");
  return options.out_dir;
}

}  // namespace shockgas::studies
