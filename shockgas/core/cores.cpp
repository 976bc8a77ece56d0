#include "shockgas/core/cores.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>
#include <thread>

#if defined(__linux__)
#include <sched.h>
#endif

namespace shockgas {

namespace {

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The processors of this process's affinity mask, or the machine's count.
std::size_t affinity_cores() {
#if defined(__linux__)
  cpu_set_t set;
  if (sched_getaffinity(0, sizeof(set), &set) == 0) return static_cast<std::size_t>(CPU_COUNT(&set));
#endif
  return std::max(1u, std::thread::hardware_concurrency());
}

// The smallest quota on the path of this process's cgroup and its ancestors
// (each level limits what is below it).
std::optional<std::size_t> cgroup_quota_cores() {
  std::istringstream lines(read_text("/proc/self/cgroup"));
  std::optional<std::size_t> cores;
  auto tighten = [&](const std::optional<std::size_t>& q) {
    if (q) cores = cores ? std::min(*cores, *q) : *q;
  };
  for (std::string line; std::getline(lines, line);) {
    // "hierarchy:controllers:path": v2 is "0::/path"; v1 lists "cpu" among its controllers.
    const std::size_t a = line.find(':'), b = line.find(':', a + 1);
    if (a == std::string::npos || b == std::string::npos) continue;
    const std::string controllers = line.substr(a + 1, b - a - 1);
    std::string path = line.substr(b + 1);
    const bool v2 = controllers.empty();
    const bool v1 = ("," + controllers + ",").find(",cpu,") != std::string::npos;
    if (!v2 && !v1) continue;
    for (;;) {
      if (v2) {  // unified, or hybrid with the v2 tree under unified/
        for (const char* root : {"/sys/fs/cgroup", "/sys/fs/cgroup/unified"})
          tighten(quota_cores(read_text(std::string(root) + path + "/cpu.max")));
      } else {
        for (const std::string& root : {std::string("/sys/fs/cgroup/cpu"), "/sys/fs/cgroup/" + controllers}) {
          const std::string quota = read_text(root + path + "/cpu.cfs_quota_us");
          const std::string period = read_text(root + path + "/cpu.cfs_period_us");
          if (!quota.empty() && !period.empty()) {
            tighten(quota_cores(quota + " " + period));
            break;
          }
        }
      }
      if (path.empty() || path == "/") break;
      path = path.substr(0, path.find_last_of('/'));
      if (path.empty()) path = "/";
    }
  }
  return cores;
}

}  // namespace

std::optional<std::size_t> quota_cores(const std::string& text) {
  std::istringstream in(text);
  std::string quota;
  double period = 0;
  if (!(in >> quota >> period) || quota == "max" || period <= 0) return std::nullopt;
  double q = 0;
  try {
    q = std::stod(quota);
  } catch (...) {
    return std::nullopt;
  }
  if (q <= 0) return std::nullopt;  // v1 writes -1 for "no quota"
  return std::max<std::size_t>(1, static_cast<std::size_t>(q / period));
}

std::size_t usable_cores() {
  const std::size_t affinity = std::max<std::size_t>(1, affinity_cores());
  const std::optional<std::size_t> quota = cgroup_quota_cores();
  return quota ? std::min(affinity, *quota) : affinity;
}

std::size_t resolved_threads(std::size_t setting) { return setting > 0 ? setting : usable_cores(); }

}  // namespace shockgas
