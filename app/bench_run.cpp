#include "bench_run.hpp"

#include <filesystem>
#include <optional>

#include "manifest.hpp"
#include "plots.hpp"
#include "run_directory.hpp"
#include "shockgas/core/interrupt.hpp"

namespace shockgas::app {

namespace fs = std::filesystem;

namespace {

// A bench of some sections only (SHOCKGAS_BENCH_SECTIONS) re-measures those:
// the earlier bench's files, as its manifest lists them, start the staging
// directory, so that the other sections' tables stay and every chart is drawn
// again from the tables as they then are.
void keep_unmeasured_sections(const RunDirectory& dir) {
  if (studies::runs_every_section()) return;
  std::error_code ec;
  if (!fs::is_directory(dir.target(), ec)) return;
  const std::optional<Manifest> earlier = read_manifest(dir.target());
  if (!earlier || earlier->scene != "bench") return;
  for (const ManifestEntry& e : earlier->files) {
    fs::create_directories((dir.staging() / e.path).parent_path());
    fs::copy_file(dir.target() / e.path, dir.staging() / e.path);
  }
}

}  // namespace

BenchOutcome run_bench(const studies::StudyOptions& options, bool force) {
  RunDirectory dir(options.out_dir, "bench", force);
  studies::StudyOptions staged = options;
  staged.out_dir = dir.staging().string();
  keep_unmeasured_sections(dir);
  studies::run_studies(staged);
  BenchOutcome outcome{options.out_dir, make_bench_charts(staged.out_dir)};
  throw_if_aborted();  // an interrupted bench is not committed, whatever its last step did
  write_manifest(dir.staging(), "bench");
  dir.commit();
  return outcome;
}

}  // namespace shockgas::app
