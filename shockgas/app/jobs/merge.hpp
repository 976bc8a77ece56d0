#pragma once
// `shockgas merge SHARD... --out DIR`: the shards of one run (shard_file.hpp)
// into the result of that run, as if it had run in one process: the same
// result.h5, summary.json, report.md and plots, bit for bit (dates, timings
// and parallel.* aside). The particles' records are read from the shards, each
// ensemble reduced in index order; the continuum solvers and the comparison
// run here, from the scene the shards carry and realization 0's final state.
//
// Refused with an InputError (exit 2, nothing written): a directory that is not
// a shard; shards of different scenes (their resolved parameters differ, the
// thread count aside) or of different builds (version or commit); slices that
// overlap or leave realizations out (the missing ones listed).
#include <string>
#include <vector>

#include "shockgas/app/run/run_options.hpp"

namespace shockgas::app {

// Returns the output directory (options.out_dir; empty: out/<scene name>).
std::string merge_shards(const std::vector<std::string>& shard_dirs, const RunOptions& options);

}  // namespace shockgas::app
