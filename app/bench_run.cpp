#include "bench_run.hpp"

#include "manifest.hpp"
#include "plots.hpp"
#include "run_directory.hpp"

namespace shockgas::app {

BenchOutcome run_bench(const studies::StudyOptions& options) {
  RunDirectory dir(options.out_dir, "bench", /*force=*/false);
  studies::StudyOptions staged = options;
  staged.out_dir = dir.staging().string();
  studies::run_studies(staged);
  BenchOutcome outcome{options.out_dir, make_bench_charts(staged.out_dir)};
  write_manifest(dir.staging(), "bench");
  dir.commit();
  return outcome;
}

}  // namespace shockgas::app
