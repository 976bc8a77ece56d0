#pragma once
// `shockgas bench` as a whole: the method studies (studies/) and their charts
// written into a staging directory and moved into place only when complete,
// with a manifest, as a run's results are (run_directory.hpp): a bench that
// fails, is interrupted or fills the disk leaves the output directory as it
// was, never new tables beside old charts.
#include <string>

#include "shockgas/studies/studies.hpp"

namespace shockgas::app {

struct BenchOutcome {
  std::string dir;       // the output directory, as given
  std::string warnings;  // for stderr: the charts' script failed (the tables are complete)
};

// force: replace an output directory that holds the results of a scene (run_target.hpp).
BenchOutcome run_bench(const studies::StudyOptions& options, bool force);

}  // namespace shockgas::app
