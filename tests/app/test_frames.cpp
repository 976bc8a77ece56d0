// The frames of an animation ([output] animation = true): their times, the
// rules of their keys, what a run records, and `shockgas animate` on a run
// without them.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <numeric>
#include <string>
#include <vector>

#include "run_command.hpp"
#include "shockgas/app/input/scene_parser.hpp"
#include "shockgas/app/output/frames.hpp"
#include "shockgas/app/output/hdf5_file.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::app {
namespace {

namespace fs = std::filesystem;

using testing_support::run;

fs::path scene_file(const std::string& name, const std::string& text) {
  const fs::path dir = testing_support::fresh_process_directory("shockgas-test-frames-", name);
  std::ofstream(dir / "scene.toml") << text;
  return dir / "scene.toml";
}

const char* kGas =
    "[initial]\nN = 300\n[particles]\nr = 0\nt_end = 50\nsamples = 6\n"
    "[continuum]\nsolvers = [\"hopf_lax\", \"godunov\"]\ncells = 300\n[output]\nplots = false\n";

TEST(Frames, LinearTimesRunFromZeroToTheEnd) {
  const Scene s = parse_scene(std::string(kGas) + "animation = true\nanimation_frames = 6\n", "s.toml");
  EXPECT_EQ(frame_times(s), (std::vector<double>{0, 10, 20, 30, 40, 50}));
}

TEST(Frames, LogTimesStartAtZeroThenSpanTheDecades) {
  const Scene s = parse_scene(std::string(kGas) +
                                  "animation = true\nanimation_frames = 5\nanimation_spacing = \"log\"\n"
                                  "animation_t_min = 0.05\n",
                              "s.toml");
  const auto t = frame_times(s);
  ASSERT_EQ(t.size(), 5u);
  EXPECT_EQ(t[0], 0.0);
  EXPECT_DOUBLE_EQ(t[1], 0.05);
  EXPECT_DOUBLE_EQ(t[2], 0.5);
  EXPECT_DOUBLE_EQ(t[3], 5.0);
  EXPECT_EQ(t[4], 50.0);
  // automatic start: t_end / 1000
  const Scene a =
      parse_scene(std::string(kGas) + "animation = true\nanimation_spacing = \"log\"\n", "s.toml");
  EXPECT_DOUBLE_EQ(frame_times(a)[1], 0.05);
}

TEST(Frames, KeysAreCheckedBeforeAnyWork) {
  auto key_of = [](const std::string& extra) {
    try {
      parse_scene(std::string(kGas) + "animation = true\n" + extra, "s.toml");
    } catch (const InputError& e) {
      return e.key();
    }
    return std::string("(accepted)");
  };
  EXPECT_EQ(key_of("animation_frames = 1\n"), "output.animation_frames");
  EXPECT_EQ(key_of("animation_spacing = \"log\"\nanimation_t_min = 50\n"), "output.animation_t_min");
  EXPECT_EQ(key_of("animation_spacing = \"cubic\"\n"), "output.animation_spacing");
  // every frame stores every body: N x frames is bounded
  EXPECT_EQ(key_of("animation_frames = 40000\n"), "output.animation_frames");
  EXPECT_EQ(key_of("animation_frames = 30\n"), "(accepted)");
}

TEST(Frames, ARunRecordsEveryFrameWithItsMass) {
  const fs::path scene = scene_file("record", std::string(kGas) + "animation = true\nanimation_frames = 6\n");
  const fs::path out = scene.parent_path() / "out";
  ASSERT_EQ(run({"run", scene.string(), "--out", out.string(), "-q"}), 0);
  const Hdf5File h5 = Hdf5File::open((out / "result.h5").string());
  EXPECT_EQ(h5.read("/animation/t").size(), 6u);
  const auto count = h5.read("/animation/clusters/count");
  const auto m = h5.read("/animation/clusters/m");
  ASSERT_EQ(count.size(), 6u);
  EXPECT_EQ(count.front(), 300.0);  // r = 0 from a lattice: every particle its own body at t = 0
  EXPECT_LT(count.back(), 300.0);   // merged by t = 50
  // each frame holds all the mass: N unit masses
  std::size_t offset = 0;
  for (double n : count) {
    const auto first = m.begin() + static_cast<std::ptrdiff_t>(offset);
    EXPECT_NEAR(std::accumulate(first, first + static_cast<std::ptrdiff_t>(n), 0.0), 300.0, 1e-9);
    offset += static_cast<std::size_t>(n);
  }
  EXPECT_EQ(offset, m.size());
  EXPECT_EQ(h5.read("/animation/fields/godunov/v").size(), 6u * 300u);
  EXPECT_EQ(h5.read("/animation/evolution/shocks").size(), 6u);
}

TEST(Frames, AnimateWithoutFramesExitsTwoNamingTheKey) {
  const fs::path scene = scene_file("none", kGas);
  const fs::path out = scene.parent_path() / "out";
  ASSERT_EQ(run({"run", scene.string(), "--out", out.string(), "-q"}), 0);
  testing::internal::CaptureStderr();
  EXPECT_EQ(run({"animate", out.string()}), 2);
  EXPECT_NE(testing::internal::GetCapturedStderr().find("output.animation"), std::string::npos);
  EXPECT_FALSE(fs::exists(out / "animation.mp4"));
  EXPECT_EQ(run({"animate", (scene.parent_path() / "no-such-run").string()}), 2);
}

// --fps, --size and --frames out of range: exit 2 before any drawing, naming the
// option, the value and what is allowed (the frames: as many as were recorded).
TEST(Frames, AnimateRefusesOptionsOutOfRangeNamingThem) {
  const fs::path scene =
      scene_file("options", std::string(kGas) + "animation = true\nanimation_frames = 6\n");
  const fs::path out = scene.parent_path() / "out";
  ASSERT_EQ(run({"run", scene.string(), "--out", out.string(), "-q"}), 0);
  const std::vector<std::vector<std::string>> refused = {
      {"--fps", "0", "from 1 to 60"},       {"--fps", "2.5", "from 1 to 60"},
      {"--size", "1279x720", "each even"},  {"--size", "640", "WxH"},
      {"--size", "8000x4000", "3840x2160"}, {"--frames", "7", "from 2 to 6"},
      {"--frames", "1", "from 2 to 6"},     {"--frames", "all", "from 2 to 6"}};
  for (const auto& r : refused) {
    std::string said;
    EXPECT_EQ(testing_support::run_saying({"animate", out.string(), r[0], r[1]}, said), 2)
        << r[0] << " " << r[1];
    EXPECT_NE(said.find(r[0] + " = \"" + r[1] + "\" is not allowed; allowed: "), std::string::npos) << said;
    EXPECT_NE(said.find(r[2]), std::string::npos) << said;
  }
  EXPECT_FALSE(fs::exists(out / "animation.mp4"));
}

// A result without its manifest entry is animated as it is, with the warning
// `shockgas info` gives (found: animate said nothing of it).
// A run of layout 1.0 (tests/data/layout-1.0): its result.h5 has no checksum of
// its own, so without its manifest nothing can check it.
TEST(Frames, AnimateWarnsThatAResultWithoutAManifestCannotBeChecked) {
  const fs::path out = scene_file("unlisted", kGas).parent_path() / "out";
  fs::copy(fs::path(SHOCKGAS_SOURCE_DIR) / "tests/data/layout-1.0", out, fs::copy_options::recursive);
  testing::internal::CaptureStderr();
  EXPECT_EQ(run({"animate", out.string()}), 2);  // no frames: refused after the check
  EXPECT_EQ(testing::internal::GetCapturedStderr().find("cannot be checked"), std::string::npos);
  fs::remove(out / "manifest.json");
  testing::internal::CaptureStderr();
  EXPECT_EQ(run({"animate", out.string()}), 2);
  EXPECT_NE(testing::internal::GetCapturedStderr().find("its integrity cannot be checked"),
            std::string::npos);
}

}  // namespace
}  // namespace shockgas::app
