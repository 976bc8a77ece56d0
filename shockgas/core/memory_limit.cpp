#include "shockgas/core/memory_limit.hpp"

#include <sys/resource.h>

#include <algorithm>
#include <fstream>
#include <limits>
#include <optional>

namespace shockgas {

namespace fs = std::filesystem;

namespace {

std::optional<double> read_number(const fs::path& file) {
  std::ifstream in(file);
  std::string word;
  if (!(in >> word) || word == "max") return std::nullopt;
  try {
    return std::stod(word);
  } catch (...) {
    return std::nullopt;
  }
}

// "memory:/path" (v1) or "0::/path" (v2) of /proc/self/cgroup.
std::optional<fs::path> cgroup_path(const fs::path& root, bool v2) {
  std::ifstream in(root / "proc/self/cgroup");
  for (std::string line; std::getline(in, line);) {
    const auto a = line.find(':'), b = line.find(':', a + 1);
    if (a == std::string::npos || b == std::string::npos) continue;
    const std::string controllers = line.substr(a + 1, b - a - 1);
    if (v2 ? line.substr(0, a) == "0" && controllers.empty()
           : ("," + controllers + ",").find(",memory,") != std::string::npos)
      return fs::path(line.substr(b + 1)).relative_path();
  }
  return std::nullopt;
}

void consider(MemoryLimit& limit, std::optional<double> bytes, const std::string& source) {
  if (bytes && *bytes < limit.bytes) limit = {std::max(0.0, *bytes), source};
}

// limit - usage of a cgroup directory (either file missing: no limit known).
std::optional<double> cgroup_room(const fs::path& dir, const char* limit_file, const char* usage_file) {
  const auto limit = read_number(dir / limit_file);
  if (!limit || *limit > 1e18) return std::nullopt;  // v1 writes "no limit" as 2^63 - 4096
  return *limit - read_number(dir / usage_file).value_or(0);
}

std::optional<double> meminfo(const fs::path& root, const std::string& key) {
  std::ifstream in(root / "proc/meminfo");
  for (std::string line; std::getline(in, line);)
    if (line.rfind(key + ":", 0) == 0) return 1024 * std::stod(line.substr(key.size() + 1));  // in kB
  return std::nullopt;
}

std::optional<double> rlimit_room(int resource, const fs::path& root, const std::string& in_use) {
  struct rlimit r {};
  if (getrlimit(resource, &r) != 0 || r.rlim_cur == RLIM_INFINITY) return std::nullopt;
  std::ifstream in(root / "proc/self/status");
  double used = 0;
  for (std::string line; std::getline(in, line);)
    if (line.rfind(in_use + ":", 0) == 0) used = 1024 * std::stod(line.substr(in_use.size() + 1));
  return static_cast<double>(r.rlim_cur) - used;
}

}  // namespace

MemoryLimit memory_limit(const fs::path& root) {
  MemoryLimit limit{std::numeric_limits<double>::infinity(), "no limit known"};
  consider(limit, meminfo(root, "MemAvailable"), "MemAvailable in /proc/meminfo");
  const fs::path cg = root / "sys/fs/cgroup";
  consider(limit, cgroup_room(cg, "memory.max", "memory.current"), "the cgroup's memory.max");
  if (const auto own = cgroup_path(root, true))
    consider(limit, cgroup_room(cg / *own, "memory.max", "memory.current"), "the cgroup's memory.max");
  if (const auto own = cgroup_path(root, false))
    consider(limit, cgroup_room(cg / "memory" / *own, "memory.limit_in_bytes", "memory.usage_in_bytes"),
             "the cgroup's memory.limit_in_bytes");
  consider(limit, cgroup_room(cg / "memory", "memory.limit_in_bytes", "memory.usage_in_bytes"),
           "the cgroup's memory.limit_in_bytes");
  consider(limit, rlimit_room(RLIMIT_AS, root, "VmSize"), "ulimit -v (address space)");
  consider(limit, rlimit_room(RLIMIT_DATA, root, "VmData"), "ulimit -d (data segment)");
  return limit;
}

}  // namespace shockgas
