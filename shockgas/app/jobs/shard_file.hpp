#pragma once
// A shard: the records of a slice of a run's realizations (ensemble_plan.hpp),
// written by `shockgas run --realizations A:B` (or --variants) and read by
// `shockgas merge`. Its directory holds result.h5, summary.json, report.md and
// manifest.json, written like a run's (into the staging directory of its run
// directory, run_directory.hpp); result.h5 holds the provenance of
// a run (scene text, overrides, resolved parameters, version) and the part
// Part::shard of the output layout (output_shard.cpp, docs/output.md): which
// slice it is and, under /shard/{e}/{k}/, the record of realization k of
// ensemble e, one dataset per field (realization_record.hpp).
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "shockgas/app/directory/result_check.hpp"
#include "shockgas/app/ensemble/ensemble_plan.hpp"
#include "shockgas/app/jobs/job_ensembles.hpp"

namespace shockgas::app {

// Writes the shard's files into dir (a staging directory, empty).
void write_shard(const std::filesystem::path& dir, const Scene& scene, const EnsemblePlan& plan,
                 ComputedRecords computed);

// What a merge needs of a shard, read without its records first.
struct ShardHeader {
  std::string dir;                                // as given
  std::map<std::string, std::string> provenance;  // the attributes of "/"
  std::map<std::string, std::string> shard;       // the attributes of "/shard"
  std::vector<std::string> overrides;
  std::uint64_t ranks = 1, threads = 1;  // of the job that computed it
  double wall_seconds = 0;               // [s]
  Verification verified =
      Verification::no_manifest;  // how its result.h5 was checked when the header was read
};
// InputError naming the directory when it holds no shard, or a result.h5
// without an attribute a shard has; FileProblem for a damaged result.h5
// (result_reader.hpp: read in a child process).
ShardHeader read_shard_header(const std::string& dir);
// Every record of the shard in dir (only /shard/..., never a whole run's
// datasets), whose result.h5 check_result_file() has passed with this verdict
// (ShardHeader::verified, or a reader's that read it first): it is not hashed
// again (a shard's may be gigabytes).
std::vector<RealizationRecord> read_shard_records(const std::string& dir, Verification checked);

}  // namespace shockgas::app
