#include "shockgas/app/directory/run_directory.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <regex>

#include "shockgas/app/directory/run_target.hpp"
#include "shockgas/app/files/durable_file.hpp"
#include "shockgas/app/files/fault.hpp"
#include "shockgas/app/files/manifest.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::app {

namespace fs = std::filesystem;

namespace {

std::string hidden(const fs::path& target, const std::string& what) {
  return "." + target.filename().string() + "." + what;
}

bool starts_with(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }

[[noreturn]] void refuse_unwritable(const fs::path& target, const std::string& reason) {
  throw InputError("--out", to_text(target.string()),
                   "a directory in a place that can be written (" + reason + ")");
}

fs::path make_staging(const fs::path& target) {
  // The pattern below (with_staging_as_target) reads this name back.
  std::string name =
      (target.parent_path() / hidden(target, "tmp-")).string() + std::to_string(getpid()) + "-XXXXXX";
  if (!mkdtemp(name.data())) refuse_unwritable(target, std::strerror(errno));
  const mode_t mask = umask(0);  // mkdtemp makes it 0700; the results get the usual mode
  umask(mask);
  chmod(name.c_str(), 0777 & ~mask);
  return name;
}

void rename_or_throw(const fs::path& from, const fs::path& to, unsigned flags) {
  if (renameat2(AT_FDCWD, from.c_str(), AT_FDCWD, to.c_str(), flags) != 0)
    throw RunError("cannot move " + from.string() + " to " + to.string() + ": " + std::strerror(errno));
}

bool exchange_unsupported(int error) { return error == EINVAL || error == ENOSYS || error == ENOTSUP; }

fs::path checked_target(const fs::path& out) {
  fs::path target = resolve_target(out);
  check_target_path(target, out.string());
  return target;
}

}  // namespace

CreatedDirectories::CreatedDirectories(const fs::path& dir) {
  std::error_code ec;
  std::vector<fs::path> missing;
  for (fs::path p = dir; !p.empty() && !fs::exists(p, ec) && p != p.parent_path(); p = p.parent_path())
    missing.insert(missing.begin(), p);
  for (const auto& p : missing) {
    if (!fs::create_directory(p, ec) && ec) {
      this->~CreatedDirectories();  // what was made so far
      refuse_unwritable(p, ec.message());
    }
    made_.push_back(p);
  }
}

CreatedDirectories::~CreatedDirectories() {
  std::error_code ec;
  for (auto it = made_.rbegin(); it != made_.rend(); ++it) fs::remove(*it, ec);  // only if empty
}

namespace {

// Why the open file fd cannot be a lock file of shockgas ("" if it can): a
// lock file is a regular file of one link that holds a process number or
// nothing, and it is written only then.
std::string foreign_lock(int fd) {
  struct stat st {};
  if (::fstat(fd, &st) != 0) return std::strerror(errno);
  if (!S_ISREG(st.st_mode)) return "not a regular file";
  if (st.st_nlink != 1)
    return "a file of " + std::to_string(st.st_nlink) + " names (a hard link to another file)";
  char text[32] = {};
  const ssize_t n = ::pread(fd, text, sizeof text, 0);
  if (n < 0) return std::strerror(errno);
  const bool number = n < static_cast<ssize_t>(sizeof text) &&
                      std::all_of(text, text + n, [](char c) { return c >= '0' && c <= '9'; });
  return number ? "" : "a file that holds other text than a process number";
}

[[noreturn]] void refuse_foreign_lock(const fs::path& lock, const std::string& out, const std::string& why) {
  throw InputError("--out", to_text(out),
                   "a directory whose lock file " + lock.string() + " is shockgas's own (this is " + why +
                       ", left as it is: remove it or give another --out)");
}

// The process number a held lock file names, for the refusal ("?" if none).
std::string holder_of(int fd) {
  char pid[32] = {};
  const ssize_t n = ::pread(fd, pid, sizeof pid - 1, 0);
  const bool number = n > 0 && std::all_of(pid, pid + n, [](char c) { return c >= '0' && c <= '9'; });
  return number ? std::string(pid, static_cast<std::size_t>(n)) : "?";
}

}  // namespace

DirectoryLock::DirectoryLock(const fs::path& target, const std::string& out)
    : path_(target.parent_path() / hidden(target, "lock")) {
  for (;;) {
    // Never through a link: a link in its place would have the process number
    // written into the file it names.
    fd_ = ::open(path_.c_str(), O_RDWR | O_CREAT | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC, 0644);
    if (fd_ < 0 && (errno == ELOOP || errno == EISDIR))
      refuse_foreign_lock(path_, out, errno == ELOOP ? "a symbolic link" : "a directory");
    if (fd_ < 0) refuse_unwritable(target, std::strerror(errno));
    if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
      const std::string pid = holder_of(fd_);
      ::close(fd_);
      fd_ = -1;
      throw InputError("--out", to_text(out),
                       "a directory that no other run is writing (shockgas process " + pid + " holds " +
                           path_.string() + ")");
    }
    // The lock file may have been removed by the previous holder between our
    // open and flock: the lock counts only on the file that is at the path.
    struct stat held {
    }, there{};
    if (::fstat(fd_, &held) == 0 && ::lstat(path_.c_str(), &there) == 0 && held.st_ino == there.st_ino &&
        held.st_dev == there.st_dev)
      break;
    ::close(fd_);
  }
  if (const std::string why = foreign_lock(fd_); !why.empty()) {
    ::close(fd_);
    fd_ = -1;
    refuse_foreign_lock(path_, out, why);
  }
  const std::string pid = std::to_string(getpid());
  if (::ftruncate(fd_, 0) == 0) (void)!::pwrite(fd_, pid.data(), pid.size(), 0);
}

DirectoryLock::~DirectoryLock() {
  if (fd_ < 0) return;
  ::unlink(path_.c_str());  // before unlocking: a waiting run then retries on a new file
  ::close(fd_);
}

RunDirectory::RunDirectory(const fs::path& out, const std::string& scene, bool force, LockOn lock_on)
    : target_(checked_target(out)),
      created_(target_.parent_path()),
      lock_(lock_on == LockOn::target ? target_ : target_.parent_path(), out.string()) {
  for (const auto& line : clear_leftovers(target_)) std::fprintf(stderr, "shockgas: %s\n", line.c_str());
  check_target_contents(target_, out.string(), scene, force);
  staging_ = make_staging(target_);
  work_ = staging_.string() + ".work";
  if (::mkdir(work_.c_str(), 0700) != 0) {
    const std::string why = std::strerror(errno);
    std::error_code ec;
    fs::remove_all(staging_, ec);
    refuse_unwritable(target_, why);
  }
}

RunDirectory::~RunDirectory() {
  std::error_code ec;
  if (!work_.empty()) fs::remove_all(work_, ec);
  if (committed_ || staging_.empty()) return;
  fs::remove_all(staging_, ec);
}

void RunDirectory::commit() {
  sync_tree(staging_);
  fault_point("swap");
  const fs::path previous = swap_into_place(staging_, target_, SwapMethod::exchange);
  sync_directory(target_.parent_path());
  committed_ = true;
  created_.keep();
  fault_point("swapped");
  std::error_code ec;
  if (!previous.empty()) fs::remove_all(previous, ec);
  fs::remove_all(work_, ec);
}

void RunDirectory::publish_copy(const std::string& scene) {
  const fs::path copy = make_staging(target_);
  try {
    fs::copy(staging_, copy, fs::copy_options::recursive);
    write_manifest(copy, scene);
    sync_tree(copy);
    const fs::path previous = swap_into_place(copy, target_, SwapMethod::exchange);
    sync_directory(target_.parent_path());
    created_.keep();
    std::error_code ec;
    if (!previous.empty()) fs::remove_all(previous, ec);
    fault_point("published");
  } catch (...) {
    std::error_code ec;
    fs::remove_all(copy, ec);
    throw;
  }
}

fs::path swap_into_place(const fs::path& staging, const fs::path& target, SwapMethod method) {
  std::error_code ec;
  if (!fs::exists(target, ec)) {
    if (renameat2(AT_FDCWD, staging.c_str(), AT_FDCWD, target.c_str(), RENAME_NOREPLACE) == 0) return {};
    if (!exchange_unsupported(errno))
      throw RunError("cannot move " + staging.string() + " to " + target.string() + ": " +
                     std::strerror(errno));
    rename_or_throw(staging, target, 0);
    return {};
  }
  if (method == SwapMethod::exchange) {
    if (renameat2(AT_FDCWD, staging.c_str(), AT_FDCWD, target.c_str(), RENAME_EXCHANGE) == 0) return staging;
    if (!exchange_unsupported(errno))
      throw RunError("cannot exchange " + staging.string() + " and " + target.string() + ": " +
                     std::strerror(errno));
  }
  // Two renames: between them the target is missing, and the previous results
  // wait at `.NAME.old-*` for clear_leftovers() to put them back.
  fs::path aside =
      staging.parent_path() /
      (hidden(target, "old-") + staging.filename().string().substr(hidden(target, "tmp-").size()));
  rename_or_throw(target, aside, 0);
  fault_point("swap:aside");
  rename_or_throw(staging, target, 0);
  return aside;
}

bool is_run_directory_leftover(const std::string& name, const std::string& dir) {
  const fs::path target(dir);
  return starts_with(name, hidden(target, "tmp-")) || starts_with(name, hidden(target, "old-")) ||
         name == hidden(target, "lock");
}

namespace {

// clear_leftovers of one target; inner: its staging directories are inside
// the directory that is being cleared (a sweep's variant).
void clear_beside(const fs::path& target, std::vector<std::string>& done) {
  const fs::path parent = target.parent_path();
  const std::string tmp = hidden(target, "tmp-"), old = hidden(target, "old-");
  std::error_code ec;
  std::vector<fs::path> staged, aside;
  for (const auto& entry : fs::directory_iterator(parent, ec)) {
    const std::string name = entry.path().filename().string();
    if (starts_with(name, tmp)) staged.push_back(entry.path());
    if (starts_with(name, old)) aside.push_back(entry.path());
  }
  if (!fs::exists(target, ec) && !aside.empty()) {
    fs::rename(aside.front(), target, ec);
    if (!ec) {
      done.push_back("put back the previous results of " + target.string() +
                     ", which a killed run had moved to " + aside.front().filename().string());
      aside.erase(aside.begin());
    }
  }
  for (const auto& dir : staged) {
    fs::remove_all(dir, ec);
    if (dir.extension() != ".work")  // a staging directory's own work directory: said with it
      done.push_back("removed " + dir.string() + ", left by a run that was killed");
  }
  for (const auto& dir : aside) {
    fs::remove_all(dir, ec);
    done.push_back("removed " + dir.string() + ", the previous results of a killed run, replaced since");
  }
}

}  // namespace

std::vector<std::string> clear_leftovers(const fs::path& target) {
  std::vector<std::string> done;
  clear_beside(target, done);
  std::error_code ec;
  std::vector<fs::path> inner;
  for (const auto& entry : fs::directory_iterator(target, ec))
    if (entry.is_directory(ec) && !entry.is_symlink(ec) && entry.path().filename().string().front() != '.')
      inner.push_back(entry.path());
  for (const auto& dir : inner) clear_beside(dir, done);
  return done;
}

std::string with_staging_as_target(const std::string& message) {
  // "/." NAME ".tmp-" PID "-" and mkdtemp's six letters or digits (make_staging).
  // Only paths into it ("/"): a message naming the staging directory itself
  // (a failed exchange with the target) keeps both names.
  static const std::regex staging(R"(/\.([^/]+)\.tmp-[0-9]+-[A-Za-z0-9]{6}(?:\.work)?(?=/))");
  return std::regex_replace(message, staging, "/$1");
}

}  // namespace shockgas::app
