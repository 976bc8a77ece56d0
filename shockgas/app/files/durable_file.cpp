#include "shockgas/app/files/durable_file.hpp"

#include <fcntl.h>
#include <sys/statvfs.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <utility>

#include "shockgas/app/files/fault.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::app {

namespace fs = std::filesystem;

namespace {

class Fd {
 public:
  explicit Fd(int fd) : fd_(fd) {}
  ~Fd() {
    if (fd_ >= 0) ::close(fd_);
  }
  Fd(const Fd&) = delete;
  Fd& operator=(const Fd&) = delete;
  int get() const { return fd_; }
  int release() { return std::exchange(fd_, -1); }

 private:
  int fd_;
};

void write_all(int fd, const char* data, std::size_t size, const fs::path& path) {
  while (size > 0) {
    const ssize_t n = ::write(fd, data, size);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw RunError(write_failure(path, std::strerror(errno)));
    data += n;
    size -= static_cast<std::size_t>(n);
  }
}

void sync_fd(int fd, const fs::path& path) {
  if (::fsync(fd) != 0 && errno != EINVAL) throw RunError(write_failure(path, std::strerror(errno)));
}

void sync_path(const fs::path& path, bool directory) {
  Fd fd(::open(path.c_str(), (directory ? O_RDONLY | O_DIRECTORY : O_RDONLY) | O_CLOEXEC));
  if (fd.get() < 0) throw RunError(write_failure(path, std::strerror(errno)));
  sync_fd(fd.get(), path);
}

}  // namespace

std::string size_text(double bytes, int digits) {
  const char* units[] = {"bytes", "kB", "MB", "GB", "TB", "PB"};
  int u = 0;
  while (bytes >= 1000 && u < 5) bytes /= 1000, ++u;
  char buf[48];
  if (u == 0) {
    std::snprintf(buf, sizeof buf, "%.0f %s", bytes, units[u]);
    return buf;
  }
  std::snprintf(buf, sizeof buf, "%.*g", digits, bytes);
  if (std::strtod(buf, nullptr) >= 1000 && u < 5)
    bytes /= 1000, ++u;  // 999.7 kB to 3 digits: 1 MB, not 1e+03 kB
  std::snprintf(buf, sizeof buf, "%.*g %s", digits, bytes, units[u]);
  return buf;
}

std::uint64_t free_bytes(const fs::path& path) {
  fs::path p = path;
  std::error_code ec;
  while (!p.empty() && !fs::exists(p, ec) && p != p.parent_path()) p = p.parent_path();
  struct statvfs s {};
  if (::statvfs(p.empty() ? "." : p.c_str(), &s) != 0) return std::numeric_limits<std::uint64_t>::max();
  return static_cast<std::uint64_t>(s.f_bavail) * s.f_frsize;
}

std::string room_note(const fs::path& path) {
  return " (the file system holding it has " + size_text(static_cast<double>(free_bytes(path))) + " free)";
}

std::string write_failure(const fs::path& path, const std::string& reason) {
  return "cannot write " + path.string() + ": " + reason + room_note(path.parent_path());
}

int open_new_file(const fs::path& path) noexcept {
  if (::unlink(path.c_str()) != 0 && errno != ENOENT) return -1;
  return ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
}

namespace {

// write_file, its fault point named after `name` (the file a temporary one
// becomes); made by open_new_file, never through a link.
void write_text(const fs::path& path, const std::string& text, const fs::path& name) {
  Fd fd(open_new_file(path));
  if (fd.get() < 0) throw RunError(write_failure(path, std::strerror(errno)));
  const std::size_t half = text.size() / 2;
  write_all(fd.get(), text.data(), half, path);
  fault_point("write:" + name.filename().string());
  write_all(fd.get(), text.data() + half, text.size() - half, path);
  sync_fd(fd.get(), path);
  if (::close(fd.release()) != 0) throw RunError(write_failure(path, std::strerror(errno)));
}

}  // namespace

void write_file(const fs::path& path, const std::string& text) { write_text(path, text, path); }

void replace_file(const fs::path& path, const std::string& text) {
  const fs::path temporary = path.string() + ".partial";
  try {
    write_text(temporary, text, path);
  } catch (...) {
    std::error_code ec;
    fs::remove(temporary, ec);  // nothing half-written beside the file it would replace
    throw;
  }
  fs::rename(temporary, path);
  sync_directory(path.parent_path());
}

void sync_directory(const fs::path& dir) { sync_path(dir, true); }

void try_sync_directory(const fs::path& dir) noexcept {
  Fd fd(::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC));
  if (fd.get() >= 0) ::fsync(fd.get());
}

void sync_tree(const fs::path& dir) {
  for (const auto& entry : fs::recursive_directory_iterator(dir)) {
    if (entry.is_symlink()) continue;
    sync_path(entry.path(), entry.is_directory());
  }
  sync_directory(dir);
}

}  // namespace shockgas::app
