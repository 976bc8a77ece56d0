#pragma once
// The command as the tests call it: `shockgas ARGS...` in this process.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "shockgas/app/command.hpp"

namespace shockgas::app::testing_support {

// Runs the command with these arguments (after the program name); its exit code.
inline int run(std::vector<std::string> args) {
  args.insert(args.begin(), "shockgas");
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  return run_command(static_cast<int>(argv.size()), argv.data());
}

// The same, what it says on stderr kept in `said`.
inline int run_saying(std::vector<std::string> args, std::string& said) {
  ::testing::internal::CaptureStderr();
  const int code = run(std::move(args));
  said = ::testing::internal::GetCapturedStderr();
  return code;
}

// An empty directory <temp>/<prefix><name of the running test>.
inline std::filesystem::path fresh_test_directory(const std::string& prefix) {
  const auto dir = std::filesystem::temp_directory_path() /
                   (prefix + ::testing::UnitTest::GetInstance()->current_test_info()->name());
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace shockgas::app::testing_support
