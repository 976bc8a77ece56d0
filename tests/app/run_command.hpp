#pragma once
// The command as the tests call it: `shockgas ARGS...` in this process.
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

}  // namespace shockgas::app::testing_support
