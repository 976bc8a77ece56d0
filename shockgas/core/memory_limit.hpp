#pragma once
// How much memory this process may still use: the smallest of the system's
// available memory, its cgroup's room and its ulimits. The resource preflight
// (shockgas/app/run/resources.hpp) holds a scene's estimate against it, the
// result reader (shockgas/app/output/result_reader.hpp) a file's declared values.
#include <filesystem>
#include <string>

namespace shockgas {

// The memory this process may still use, and where that limit comes from.
struct MemoryLimit {
  double bytes = 0;
  std::string source;  // "MemAvailable in /proc/meminfo", "the cgroup's memory.max", "ulimit -v", ...
};

// The smallest of: the system's available memory, the limit of the process's
// cgroup (v2 memory.max, v1 memory.limit_in_bytes) less its usage, and the
// address-space and data limits (ulimit) less what is in use. root: where /proc
// and /sys are found (tests give a tree of their own).
MemoryLimit memory_limit(const std::filesystem::path& root = "/");

}  // namespace shockgas
