#pragma once
// Running a scene: every part the scene asks for, then the result files.
//
// Output directory DIR: result.h5, summary.json (both laid out as docs/output.md
// says), report.md, *.png, manifest.json. DIR is whole or absent: the run
// writes into a staging directory beside it and replaces DIR by it only when
// everything is written, so a failed, interrupted or killed run leaves DIR as
// it was (docs/output.md, "The run directory"). A run in one process computes
// here (run/run_internal.hpp); a shard, an MPI job or a run that keeps
// checkpoints through parallel_run.hpp.
#include <string>

#include "shockgas/app/run/run_options.hpp"
#include "shockgas/app/scene/scene.hpp"

namespace shockgas::app {

// Returns the output directory. Throws InputError for input that the scene's
// parts, the resources or the output directory refuse before any work (nothing
// written), RunError on a failure during the run and Interrupted when an
// interrupt was requested (core/interrupt.hpp); in both DIR is left as it was.
std::string run_scene(const Scene& scene, const RunOptions& options);

}  // namespace shockgas::app
