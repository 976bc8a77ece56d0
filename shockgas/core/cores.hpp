#pragma once
// How many cores this process may use: what "all cores" means for the thread
// options. Not the machine's count (std::thread::hardware_concurrency) but the
// processors of its CPU affinity (taskset, a batch scheduler's binding), capped by
// a container's CPU quota (cgroup v2 cpu.max or v1 cpu.cfs_quota_us).
#include <cstddef>
#include <optional>
#include <string>

namespace shockgas {

// The usable cores, >= 1: the affinity's processors, at most the whole cores of
// the quota (a quota of 1.5 cores gives 1: a second thread would be throttled).
std::size_t usable_cores();

// The threads "threads = n" means for this process: n, or for 0 the cores it
// may use (usable_cores: its CPU affinity, as mpirun and srun bind ranks to
// cores, and a container's quota).
std::size_t resolved_threads(std::size_t setting);

// The whole cores a cgroup quota allows: `text` is cpu.max ("max 100000" or
// "150000 100000") or, for cgroup v1, "quota period" from cpu.cfs_quota_us and
// cpu.cfs_period_us (quota -1 = none). nullopt when there is no quota.
std::optional<std::size_t> quota_cores(const std::string& text);

}  // namespace shockgas
