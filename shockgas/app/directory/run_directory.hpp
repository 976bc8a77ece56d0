#pragma once
// The output directory of a run, whole or absent (docs/output.md, "The run
// directory").
//
// A run writes everything (result, summary, report, plots, manifest) into a
// staging directory beside its target, `.NAME.tmp-<pid>-<random>`, and moves it
// into place only when it is complete and on the disk (fsync): by one
// renameat2(RENAME_EXCHANGE) when the target exists, whose previous contents
// are then removed, by one rename otherwise. A failed, interrupted or killed
// run therefore leaves the target as it was. A lock beside the target
// (`.NAME.lock`, flock) keeps two runs out of one directory; the next run into
// it removes the staging directories that killed runs left (and, on a file
// system without RENAME_EXCHANGE, puts back previous results that a run killed
// half-way through its two renames had moved aside). An interrupted
// run's checkpoint (NAME/checkpoint.bin, checkpoint.hpp) stays until the
// finished run replaces NAME.
#include <filesystem>
#include <string>
#include <vector>

namespace shockgas::app {

// The directories a run made above its target (`out/` of `out/default`),
// removed again, if empty, unless kept.
class CreatedDirectories {
 public:
  explicit CreatedDirectories(const std::filesystem::path& dir);  // creates dir and what is missing above it
  ~CreatedDirectories();
  CreatedDirectories(const CreatedDirectories&) = delete;
  CreatedDirectories& operator=(const CreatedDirectories&) = delete;
  void keep() { made_.clear(); }

 private:
  std::vector<std::filesystem::path> made_;  // outermost first
};

// flock on `.NAME.lock` beside the target, held by one run at a time; the
// file is removed when the lock is released.
class DirectoryLock {
 public:
  DirectoryLock(const std::filesystem::path& target, const std::string& out);  // InputError if held
  ~DirectoryLock();
  DirectoryLock(const DirectoryLock&) = delete;
  DirectoryLock& operator=(const DirectoryLock&) = delete;

 private:
  std::filesystem::path path_;
  int fd_ = -1;
};

class RunDirectory {
 public:
  // Checks the target (run_target.hpp: InputError naming --out, before any
  // work), creates the missing directories above it, takes its lock, clears
  // what killed runs left and creates the staging directory. out: --out as
  // given (messages); scene: the name of the scene about to run.
  RunDirectory(const std::filesystem::path& out, const std::string& scene, bool force);
  // Without commit(): removes the staging directory (and the directories it
  // created above the target, if empty), releases the lock.
  ~RunDirectory();
  RunDirectory(const RunDirectory&) = delete;
  RunDirectory& operator=(const RunDirectory&) = delete;

  const std::filesystem::path& staging() const { return staging_; }  // where the run writes now
  const std::filesystem::path& target() const { return target_; }

  // Syncs the staging directory to the disk, moves it into place and removes
  // the previous contents. RunError if the move fails (the target unchanged).
  void commit();

  // For a command whose results grow in steps, each step whole (`shockgas
  // tail`): a copy of the staging directory, with a manifest of scene's, moves
  // into place as commit() moves the staging directory; the staging directory
  // stays, for the next step. RunError if it fails (the target as it was).
  void publish_copy(const std::string& scene);

 private:
  std::filesystem::path target_;
  CreatedDirectories created_;
  DirectoryLock lock_;
  std::filesystem::path staging_;
  bool committed_ = false;
};

// message with each path into a staging directory written as the path into its
// target ("/x/.D.tmp-812-Ab3dEf/result.h5" -> "/x/D/result.h5"): a failure is
// read after the staging directory has been removed, and names the file the
// user asked for.
std::string with_staging_as_target(const std::string& message);

// How a finished staging directory replaces an existing target: one atomic
// exchange, or (file systems without RENAME_EXCHANGE) the target moved aside
// to `.NAME.old-*`, the staging directory renamed, the old one removed.
enum class SwapMethod { exchange, two_renames };
// Moves staging to target (which may not exist); the previous contents end up
// at the returned path (to be removed), or it is empty when there were none.
std::filesystem::path swap_into_place(const std::filesystem::path& staging,
                                      const std::filesystem::path& target, SwapMethod method);

// What killed runs into target left beside it: staging directories are
// removed, and previous results moved aside by a run killed between its two
// renames are put back where the target is missing. Returns one line per action
// (for a note on stderr). Call with the target's lock held.
std::vector<std::string> clear_leftovers(const std::filesystem::path& target);

}  // namespace shockgas::app
