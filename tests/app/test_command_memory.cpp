// The memory of `shockgas run` (docs/performance.md, "Memory of the command"):
// the whole process's peak resident memory stays within 40 bytes per particle
// of what it held before the run, plus a fixed 8 MiB. Realization 0's final
// state goes to its state file in chunks (shockgas/app/records/state_file.hpp) instead of a
// whole copy beside the engine's (24 bytes per particle, 48 with the copy that
// ordered it), which put the command at 81 bytes per particle.
//
// Measured by the kernel: /proc/self/clear_refs resets the peak (VmHWM) before
// the run. Not under a sanitizer, whose shadow memory and quarantine are
// resident too.
#include <gtest/gtest.h>
#include <malloc.h>

#include <fstream>
#include <optional>
#include <string>

#include "app/run_command.hpp"

namespace shockgas::app {
namespace {

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
constexpr bool kSanitized = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
constexpr bool kSanitized = true;
#else
constexpr bool kSanitized = false;
#endif
#else
constexpr bool kSanitized = false;
#endif

// A field of /proc/self/status in bytes ("VmRSS", "VmHWM").
std::optional<double> status_bytes(const std::string& field) {
  std::ifstream in("/proc/self/status");
  for (std::string line; std::getline(in, line);)
    if (line.rfind(field + ":", 0) == 0) return 1024.0 * std::stod(line.substr(field.size() + 1));
  return std::nullopt;
}

// Resets VmHWM to the current resident size (Linux 4.0 and later).
bool reset_peak() {
  std::ofstream out("/proc/self/clear_refs");
  out << "5";
  out.flush();
  return static_cast<bool>(out);
}

TEST(CommandMemory, TheRunStaysWithinFortyBytesPerParticle) {
  if (kSanitized) GTEST_SKIP() << "a sanitizer's memory is resident too";
  const std::size_t N = 1000000;
  const auto dir = testing_support::fresh_test_directory("shockgas-test-memory-");
  std::ofstream(dir / "scene.toml") << "[initial]\nN = " << N
                                    << "\nseed = 1\n[particles]\nr = 0.9\ndelta = 1e-2\nt_end = 10\n";
  malloc_trim(0);
  const std::optional<double> before = status_bytes("VmRSS");
  if (!before || !reset_peak()) GTEST_SKIP() << "no /proc/self/status or clear_refs here";
  std::string said;
  ASSERT_EQ(
      testing_support::run_saying({"run", (dir / "scene.toml").string(), "--out", (dir / "out").string(),
                                   "-q", "--no-plots", "--set", "particles.threads=1"},
                                  said),
      0)
      << said;
  const double grown = *status_bytes("VmHWM") - *before;
  EXPECT_LE(grown, 40.0 * N + 8.0 * (1 << 20)) << grown / N << " bytes per particle";
}

}  // namespace
}  // namespace shockgas::app
