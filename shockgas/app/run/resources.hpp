#pragma once
// The resource preflight: the memory and the disk a scene needs, estimated
// from its keys before any work, against what the process may use. A scene
// that cannot fit is refused (InputError, exit 2) naming the key that needs
// most, the estimate and the limit.
//
// The estimate adds, per item, a measured cost per element (bytes per particle
// of the engine, per cell of the continuum solvers, per sample, bin and frame
// of the records) to the process's own base; tests/app/test_resources.cpp
// holds it against the peak memory and the result sizes of real runs.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "shockgas/app/scene/scene.hpp"
#include "shockgas/core/error.hpp"
#include "shockgas/core/memory_limit.hpp"

namespace shockgas::app {

// One item of an estimate: the scene key that sets its size, and its bytes.
struct ResourceItem {
  std::string key;  // "initial.N", "particles.histogram_bins", ... ("" for the process base)
  std::string what;
  double bytes = 0;
  std::vector<std::string> factors = {};  // other keys the size grows with ("particles.samples")
};

struct ResourceEstimate {
  std::vector<ResourceItem> items;
  double total() const;
  const ResourceItem& largest() const;
};

// Peak memory of a run of scene (a sweep: its largest variant, with every
// variant's initial condition, which a sweep builds up front).
ResourceEstimate estimate_memory(const Scene& scene);
// Bytes the run directory will hold (a sweep: every variant and its own files);
// plots: whether the run draws them (--no-plots).
ResourceEstimate estimate_disk(const Scene& scene, bool plots);

// Refuses a scene that does not fit: InputError located at the scene's key
// (memory) or naming --out (disk: the file system that will hold the results).
void check_resources(const Scene& scene, const std::filesystem::path& out, bool plots);

// x, v, m of one body in memory.
inline constexpr double kBodyBytes = 24;
// The program and its libraries, resident (measured 24.5 MB).
inline constexpr double kProcessBaseBytes = 26e6;

// Refuses work whose estimate exceeds the memory this process may still use:
// throws refusal(allowed), allowed = "WHAT that fits in the memory available:
// it needs about ... (its largest item), ... available (where the limit comes from)".
void require_memory(const ResourceEstimate& memory, const std::string& what,
                    const std::function<InputError(const std::string& allowed)>& refusal);

// Threads a process may run: at most kThreadsPerCore for each core it may use
// (usable_cores, core/cores.hpp: its CPU affinity and quota). More only wait
// for the cores, and a count without bound took every process slot of the
// system. Throws refusal(allowed) for more.
inline constexpr std::size_t kThreadsPerCore = 8;
void require_threads(std::size_t threads,
                     const std::function<InputError(const std::string& allowed)>& refusal);

// The memory half of check_resources, and the threads (particles.threads of
// the scene and of every variant), for work that writes no directory too (the
// Python module's calls, which would otherwise end in the kernel's
// out-of-memory killer).
void check_memory(const Scene& scene);

}  // namespace shockgas::app
