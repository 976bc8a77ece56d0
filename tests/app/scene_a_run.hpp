#pragma once
// A run of kSceneA (run_dir_checks.hpp) without plots, made by the command in a
// child process: the sound directory that damage and integrity tests copy.
#include <filesystem>
#include <string>

#include "child_run.hpp"
#include "run_dir_checks.hpp"

namespace shockgas::app::testing {

// <fresh_dir(name)>/run, the run's output directory.
inline fs::path scene_a_run(const std::string& name) {
  const fs::path root = fresh_dir(name);
  write_text(root / "scene.toml", std::string(kSceneA) + "[output]\nplots = false\n");
  const auto [code, err] =
      run_child({"run", (root / "scene.toml").string(), "--out", (root / "run").string(), "-q"});
  EXPECT_EQ(code, 0) << err;
  return root / "run";
}

}  // namespace shockgas::app::testing
