#pragma once
// Paths under the temporary directory that belong to this test process alone:
// test binaries of another checkout or build may run at the same time, and a
// fixed name there would let one run delete the other's files mid-test.
//
// Every path handed out is removed when the test process exits, if all its
// tests passed; after a failure they stay for inspection (the test's output
// names them). SHOCKGAS_KEEP_TEST_FILES=1 keeps them always.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <string>
#include <system_error>
#include <vector>

namespace shockgas::testing_support {

// The paths of this process, removed at its exit (see above).
class TempPathRegistry {
 public:
  static TempPathRegistry& instance() {
    static TempPathRegistry registry;
    return registry;
  }

  void add(const std::filesystem::path& path) {
    const std::lock_guard<std::mutex> lock(mutex_);
    paths_.push_back(path);
  }

  TempPathRegistry(const TempPathRegistry&) = delete;
  TempPathRegistry& operator=(const TempPathRegistry&) = delete;

  // The registry is created at the first path, after googletest's UnitTest
  // singleton, so it is destroyed before it and may still ask for the verdict.
  ~TempPathRegistry() {
    const char* keep = std::getenv("SHOCKGAS_KEEP_TEST_FILES");
    if ((keep != nullptr && std::string(keep) == "1") || !::testing::UnitTest::GetInstance()->Passed())
      return;
    for (const auto& path : paths_) {
      std::error_code ignored;  // a path a test never created, or a mount point: leave it
      std::filesystem::remove_all(path, ignored);
    }
  }

 private:
  TempPathRegistry() = default;
  std::mutex mutex_;
  std::vector<std::filesystem::path> paths_;
};

// <temp>/<prefix><pid>-<name>; nothing is created, the path is removed at exit.
inline std::filesystem::path process_temp_path(const std::string& prefix, const std::string& name) {
  auto path = std::filesystem::temp_directory_path() / (prefix + std::to_string(getpid()) + "-" + name);
  TempPathRegistry::instance().add(path);
  return path;
}

// The same path, emptied and created as a directory.
inline std::filesystem::path fresh_process_directory(const std::string& prefix, const std::string& name) {
  auto dir = process_temp_path(prefix, name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace shockgas::testing_support
