#pragma once
// How a scene is run: where its results go, what is shown and drawn, which
// slice of it (a shard), checkpoints and resume (jobs/run_scene.hpp runs it).
#include <functional>
#include <string>

#include "shockgas/app/scene/scene.hpp"

namespace shockgas::app {

struct RunOptions {
  std::string out_dir;   // results directory; empty = out/<scene name>
  bool progress = true;  // progress on stderr for runs longer than a second
  bool plots = true;     // make plots (also needs scene output.plots)
  // A shard (docs/cluster.md): only these realizations of each ensemble ("A:B",
  // half-open), and only these variants of a sweep; written for `shockgas merge`.
  std::string realizations;
  std::string variants;
  // Keep checkpoints of the particle ensembles in the output directory
  // (output.checkpoint_minutes; a host that turns SIGTERM and SIGINT into
  // checkpoint requests: the command), for a run of one process.
  bool checkpoint = false;
  // Continue from the checkpoint in out_dir (the scene is the checkpoint's).
  bool resume = false;
  // Also told of the progress of each stage ("particles", "continuum/<solver>"):
  // the fraction of the stage done in [0, 1] and the simulated time reached.
  // Called from the run's threads, one call at a time; a host's own display.
  std::function<void(const std::string& stage, double fraction, double sim_time)> on_progress;
  bool force = false;  // replace a directory that holds another scene's results
};

}  // namespace shockgas::app
