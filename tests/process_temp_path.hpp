#pragma once
// Paths under the temporary directory that belong to this test process alone:
// test binaries of another checkout or build may run at the same time, and a
// fixed name there would let one run delete the other's files mid-test.
#include <unistd.h>

#include <filesystem>
#include <string>

namespace shockgas::testing_support {

// <temp>/<prefix><pid>-<name>; nothing is created.
inline std::filesystem::path process_temp_path(const std::string& prefix, const std::string& name) {
  return std::filesystem::temp_directory_path() / (prefix + std::to_string(getpid()) + "-" + name);
}

// The same path, emptied and created as a directory.
inline std::filesystem::path fresh_process_directory(const std::string& prefix, const std::string& name) {
  const auto dir = process_temp_path(prefix, name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace shockgas::testing_support
