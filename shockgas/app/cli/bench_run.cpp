#include "shockgas/app/cli/bench_run.hpp"

#include <filesystem>
#include <optional>

#include "shockgas/app/directory/result_check.hpp"
#include "shockgas/app/directory/run_directory.hpp"
#include "shockgas/app/files/manifest.hpp"
#include "shockgas/app/report/plots.hpp"
#include "shockgas/core/interrupt.hpp"

namespace shockgas::app {

namespace fs = std::filesystem;

namespace {

// A bench of some sections only (SHOCKGAS_BENCH_SECTIONS) re-measures those:
// the earlier bench's tables (CSV and the failure table) start the staging
// directory, so that the other sections' tables and failures stay, and every
// chart is drawn again from the tables as they then are. The earlier bench must
// be as its manifest records: nothing unchecked is carried into the new one.
void keep_unmeasured_sections(const RunDirectory& dir) {
  if (studies::runs_every_section()) return;
  std::error_code ec;
  if (!fs::is_directory(dir.target(), ec)) return;
  const std::optional<Manifest> earlier = read_manifest(dir.target());
  if (!earlier || earlier->scene != "bench") return;
  const std::string differences = differences_of(check_listed_files(dir.target(), *earlier, ""));
  if (!differences.empty())
    throw result_problem(dir.target().string(), "not as its manifest.json records",
                         differences +
                             "; a bench of some sections keeps the others' tables only from an intact "
                             "bench: run every section");
  for (const ManifestEntry& e : earlier->files) {
    const std::string kind = fs::path(e.path).extension().string();
    if (kind != ".csv" && kind != ".md") continue;
    fs::create_directories((dir.staging() / e.path).parent_path());
    fs::copy_file(dir.target() / e.path, dir.staging() / e.path);
  }
}

}  // namespace

BenchOutcome run_bench(const studies::StudyOptions& options, bool force) {
  studies::runs_every_section();  // a section that does not exist is refused before anything is made
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
