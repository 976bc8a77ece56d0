// A scene that follows a change: particles.solver = "auto" on the gallery's
// sticky scenes runs the exact hull as they stand and the event engine after
// --set particles.r=0.5, saying which; "hull" itself still refuses r > 0.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "run_command.hpp"
#include "shockgas/app/input/scene_parser.hpp"
#include "shockgas/app/scene/scene.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::app {
namespace {

namespace fs = std::filesystem;
using particles::ParticleSolver;

const fs::path kGallery = fs::path(SHOCKGAS_SOURCE_DIR) / "data/scenes/gallery";

// The gallery's scenes that say solver = "auto" (the sticky gas, r = 0).
std::vector<fs::path> automatic_scenes() {
  std::vector<fs::path> out;
  for (const auto& entry : fs::directory_iterator(kGallery)) {
    std::ifstream in(entry.path());
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (entry.path().extension() == ".toml" && text.find("solver = \"auto\"") != std::string::npos)
      out.push_back(entry.path());
  }
  return out;
}

// As they stand they run the hull, and their resolved parameters (which decide
// the results, scene.hpp physics_of) are those of solver = "hull": the same runs.
TEST(SceneFollowsChange, TheGallerysAutoScenesRunTheHullAsBefore) {
  const auto scenes = automatic_scenes();
  ASSERT_GE(scenes.size(), 4u);  // sine, n-wave, merging shocks, delta-shock
  for (const auto& path : scenes) {
    const Scene s = load_scene(path.string());
    EXPECT_EQ(s.particles.solver, ParticleSolver::hull) << path;
    EXPECT_NE(s.solver_note.find("the exact hull"), std::string::npos) << path << ": " << s.solver_note;
    const Scene hull = load_scene(path.string(), {"particles.solver=\"hull\""});
    EXPECT_EQ(physics_of(resolved_scene_text(s)), physics_of(resolved_scene_text(hull))) << path;
  }
}

TEST(SceneFollowsChange, AnInelasticGasRunsTheEventEngine) {
  for (const auto& path : automatic_scenes()) {
    const Scene s = load_scene(path.string(), {"particles.r=0.5"});
    EXPECT_EQ(s.particles.solver, ParticleSolver::events) << path;
    EXPECT_NE(s.solver_note.find("the event engine, as particles.r = 0.5 > 0"), std::string::npos)
        << path << ": " << s.solver_note;
  }
}

TEST(SceneFollowsChange, AnExplicitHullStillRefusesAnInelasticGas) {
  try {
    parse_scene("[particles]\nr = 0\nsolver = \"hull\"\n", "hull.toml", {"particles.r=0.5"});
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "particles.solver");
    EXPECT_NE(std::string(e.what()).find("\"auto\""), std::string::npos) << e.what();  // the way out
  }
}

TEST(SceneFollowsChange, EachSweepVariantChoosesForItself) {
  const Scene s = parse_scene(
      "[particles]\nr = 0\nsolver = \"auto\"\nt_end = 10\n[sweep]\nvariants = [\"particles.r=0\", "
      "\"particles.r=0.5\"]\n",
      "sweep.toml");
  const auto variants = expand_sweep(s);
  ASSERT_EQ(variants.size(), 2u);
  EXPECT_EQ(variants[0].particles.solver, ParticleSolver::hull);
  EXPECT_EQ(variants[1].particles.solver, ParticleSolver::events);
}

TEST(SceneFollowsChange, TheCommandSaysWhichItChose) {
  const fs::path dir = testing_support::fresh_test_directory("shockgas-test-auto-");
  std::ofstream(dir / "scene.toml")
      << "[initial]\nN = 200\n[particles]\nr = 0\nsolver = \"auto\"\nt_end = 20\n"
         "samples = 4\n[output]\nplots = false\n";
  std::string said;
  ASSERT_EQ(testing_support::run_saying({"run", (dir / "scene.toml").string(), "--set", "particles.r=0.5",
                                         "--out", (dir / "out").string(), "-q"},
                                        said),
            0)
      << said;
  EXPECT_NE(
      said.find("shockgas: note: particles.solver = \"auto\": the event engine, as particles.r = 0.5 > 0"),
      std::string::npos)
      << said;
}

}  // namespace
}  // namespace shockgas::app
