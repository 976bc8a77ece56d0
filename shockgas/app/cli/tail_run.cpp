#include "shockgas/app/cli/tail_run.hpp"

#include "shockgas/app/directory/run_directory.hpp"
#include "shockgas/app/run/tail_resources.hpp"

namespace shockgas::app {

std::string run_tail(studies::TailStudyOptions options, bool force) {
  studies::validate_tail_study(options);  // before the directory is touched
  check_tail_resources(options);          // and before anything is allocated
  RunDirectory dir(options.out_dir, "tail", force);
  studies::TailStudyOptions staged = options;
  staged.out_dir = dir.staging().string();
  staged.size_written = [&dir] { dir.publish_copy("tail"); };
  studies::run_tail_study(staged);
  return options.out_dir;
}

}  // namespace shockgas::app
