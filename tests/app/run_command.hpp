#pragma once
// The command as the tests call it: `shockgas ARGS...` in this process.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "process_temp_path.hpp"
#include "shockgas/app/cli/command.hpp"

namespace shockgas::app::testing_support {

using shockgas::testing_support::fresh_process_directory;
using shockgas::testing_support::process_temp_path;

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

// An empty directory <temp>/<prefix><pid>-<name of the running test>.
inline std::filesystem::path fresh_test_directory(const std::string& prefix) {
  return shockgas::testing_support::fresh_process_directory(
      prefix, ::testing::UnitTest::GetInstance()->current_test_info()->name());
}

}  // namespace shockgas::app::testing_support
