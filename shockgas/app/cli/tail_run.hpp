#pragma once
// `shockgas tail` (shockgas/studies/tail_study.hpp) into its output directory: the
// directory is checked and locked as a run's (run_target.hpp,
// run_directory.hpp), the study writes into a staging directory, and each time
// a size is done a copy of its files, with a manifest (scene "tail"), replaces
// the output directory whole. A failure, an interruption or a full disk leaves
// the directory as the last finished size left it (or as it was before the
// first): never a file cut short, and hours of finished sizes are not lost to
// a late interrupt.
#include <string>

#include "shockgas/studies/tail_study.hpp"

namespace shockgas::app {

// Returns the output directory as given.
std::string run_tail(studies::TailStudyOptions options, bool force);

}  // namespace shockgas::app
