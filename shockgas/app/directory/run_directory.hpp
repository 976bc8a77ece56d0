#pragma once
// The output directory of a run, whole or absent (docs/output.md, "The run
// directory"): the one mechanism by which every command writes a directory
// (run, shard, merge, resume, stats, animate, bench, tail, the Python module's
// run(out=...)).
//
// Before any work a command takes the lock beside its target
// (`.NAME.lock`, flock; refused at once, naming the holder, while another run
// holds it), clears what killed runs left, checks what the target holds and
// makes the staging directory `.NAME.tmp-<pid>-<random>` beside it, and a work
// directory `.NAME.tmp-<pid>-<random>.work` for its temporary files (a
// realization's states file while no checkpoint refers to it). Everything is
// written into the staging directory and moved into place only when it is
// complete and on the disk (fsync): by one renameat2(RENAME_EXCHANGE) when the
// target exists, whose previous contents are then removed, by one rename
// otherwise. A failed, interrupted or killed run therefore leaves the target
// as it was; only a checkpoint it saved (checkpoint.hpp: NAME/checkpoint.bin
// and the files it refers to) goes into the target before the end, to be
// resumed. The next run into it removes the staging and work directories that
// killed runs left (also those of a sweep's variants, inside it) and, on a
// file system without RENAME_EXCHANGE, puts back previous results that a run
// killed half-way through its two renames had moved aside.
//
// The lock file is opened without following a link, and a lock file that is
// not shockgas's own (a link, a file with other links, other text than a
// process number) is refused, never written.
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
// file is removed when the lock is released. InputError naming --out when
// another process holds it (its process number said) or when the file in its
// place is not a lock file of shockgas (a link, a file with other links, other
// text), which is left as it is.
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
  // what killed runs left, checks the target's contents and creates the
  // staging and work directories. out: --out as given (messages); scene: the
  // name of the scene about to run.
  // lock_on: the lock of the target itself, or of the directory that holds it
  // (a sweep's variant changed by `shockgas animate`: no run may replace the
  // sweep meanwhile, and the variant's staging directory is inside the sweep).
  enum class LockOn { target, enclosing };
  RunDirectory(const std::filesystem::path& out, const std::string& scene, bool force,
               LockOn lock_on = LockOn::target);
  // Without commit(): removes the staging and work directories (and the
  // directories it created above the target, if empty), releases the lock.
  ~RunDirectory();
  RunDirectory(const RunDirectory&) = delete;
  RunDirectory& operator=(const RunDirectory&) = delete;

  const std::filesystem::path& staging() const { return staging_; }  // where the run writes now
  const std::filesystem::path& work() const { return work_; }        // its temporary files
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
  std::filesystem::path staging_, work_;
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

// What killed runs into target left beside it: staging and work directories
// are removed, and previous results moved aside by a run killed between its
// two renames are put back where the target is missing; then the same inside
// target, for each directory in it (a sweep's variants, which `shockgas
// animate` stages beside themselves). Returns one line per action (for a note
// on stderr). Call with the target's lock held.
std::vector<std::string> clear_leftovers(const std::filesystem::path& target);

// Whether name (an entry beside a directory `dir`) is what a command into
// dir makes there or leaves when killed: its lock, staging, work or
// moved-aside directory.
bool is_run_directory_leftover(const std::string& name, const std::string& dir);

}  // namespace shockgas::app
