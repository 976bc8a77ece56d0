#pragma once
// The fixture of the checkpoint tests (test_checkpoint.cpp,
// test_running_states.cpp): a small ensemble scene, interrupted runs of it
// made by hand, and the command run in this process.
#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <thread>

#include "app/run_command.hpp"
#include "app/run_comparison.hpp"
#include "app/run_dir_checks.hpp"
#include "shockgas/app/ensemble/checkpointer.hpp"
#include "shockgas/app/ensemble/realization_pool.hpp"
#include "shockgas/app/input/scene_parser.hpp"
#include "shockgas/app/output/frames.hpp"
#include "shockgas/app/records/checkpoint.hpp"
#include "shockgas/app/records/run_state_file.hpp"
#include "shockgas/app/records/state_file.hpp"
#include "shockgas/core/error.hpp"
#include "shockgas/particles/simulate.hpp"
#include "shockgas/version.hpp"

namespace shockgas::app {

namespace fs = std::filesystem;

inline const char* kScene =
    "[initial]\nN = 300\n[particles]\nr = 0.5\nt_end = 15\nsamples = 7\nrealizations = 5\n"
    "histogram_bins = 10\nsnapshots = [4]\n[continuum]\nsolvers = [\"hopf_lax\"]\ncells = 200\n[compare]\n"
    "[output]\nplots = false\n";

inline std::string bytes_of(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream out;
  out << in.rdbuf();
  return out.str();
}

class Checkpoints : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = testing_support::fresh_test_directory("shockgas-test-checkpoint-");
    std::ofstream(path("scene.toml")) << kScene;
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  // Realizations `indices` of the scene, as a run keeps them (realization 0 with its states).
  std::vector<RealizationRecord> records(const Scene& scene, std::vector<std::uint64_t> indices) const {
    const InitialCondition ic(scene.initial);
    std::vector<RealizationRecord> out;
    for (std::uint64_t k : indices)
      out.push_back({0, k, particles::run_realization(ic, k, particle_params(scene))});
    return out;
  }
  // The checkpoint of an interrupted run of scene.toml into `out` that finished `indices`.
  void interrupted_run(const std::string& out, std::vector<std::uint64_t> indices) const {
    const Scene scene = load_scene(path("scene.toml"));
    write_checkpoint(path(out), make_checkpoint(scene, "", "", records(scene, indices)));
  }
  // Runs the command; returns its exit code and keeps what it said.
  int command(std::vector<std::string> args) { return testing_support::run_saying(std::move(args), said_); }
  fs::path dir_;
  std::string said_;
};

}  // namespace shockgas::app
