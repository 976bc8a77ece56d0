// Values a careless or hostile user gives (findings of a hostile pass): an
// override that smuggles a second key after a line break, control characters
// and NUL in a scene's name, values whose refusal named a key the user never
// wrote, and library text instead of a message. Each is refused before any
// work, exit 2, with a message naming the user's own key and value.
#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "child_run.hpp"
#include "run_dir_checks.hpp"

namespace shockgas::app {
namespace {

using namespace testing;

const char* kSmall =
    "[scene]\nname = \"small\"\n[initial]\nN = 200\n[particles]\nr = 0.5\nt_end = 5\n"
    "realizations = 2\n[output]\nplots = false\n";

// The command on scene text in root: {status, stderr}; bad input writes nothing.
std::pair<int, std::string> run_scene_text(const fs::path& root, const std::string& text,
                                           std::vector<std::string> extra = {}) {
  write_text(root / "scene.toml", text);
  std::vector<std::string> args = {"run", (root / "scene.toml").string(), "--out", (root / "out").string(),
                                   "-q"};
  args.insert(args.end(), extra.begin(), extra.end());
  auto result = run_child(args);
  if (result.first == 2) {
    EXPECT_FALSE(fs::exists(root / "out")) << result.second;
  }
  return result;
}

// Everything after a line break in a --set was dropped: `initial.N=3000\nN=5`
// ran N = 3000 and said nothing. An override is one key and one TOML value.
TEST(HostileValues, AnOverrideIsOneKeyAndOneValue) {
  const fs::path root = fresh_dir("hostile-set");
  for (const std::string set : {"initial.N=3000\nN=5", "initial.N=3000\r\n[particles]\nr=0.9",
                                "scene.name=abc\ndef", "initial.N\n=300"}) {
    const auto [code, err] = run_scene_text(root, kSmall, {"--set", set});
    EXPECT_EQ(code, 2) << set << "\n" << err;
    EXPECT_NE(err.find("--set"), std::string::npos) << err;
    EXPECT_EQ(err.find('\r'), std::string::npos) << err;
    EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << "one line: " << err;
  }
  // One value with a comment after it, or a bare word, is still one value.
  for (const std::string set : {"initial.N=300 # more", "initial.positions=random"}) {
    const auto [code, err] = run_scene_text(root, kSmall, {"--set", set});
    EXPECT_EQ(code, 0) << set << "\n" << err;
    fs::remove_all(root / "out");
  }
}

// A NUL in the scene's name cut the message there; an escape sequence was sent
// to the terminal as it was. Control characters are written as escapes.
TEST(HostileValues, ControlCharactersInAValueAreShownAsEscapes) {
  const fs::path root = fresh_dir("hostile-control");
  const auto nul = run_scene_text(root, "[scene]\nname = \"ab\\u0000cd\"\n[initial]\nN = 100\n[particles]\n");
  EXPECT_EQ(nul.first, 2) << nul.second;
  EXPECT_NE(nul.second.find("scene.name = \"ab\\0cd\" is not allowed; allowed: "), std::string::npos)
      << nul.second;
  const auto esc =
      run_scene_text(root, "[scene]\nname = \"ab\\u001b[31mRED\"\n[initial]\nN = 100\n[particles]\n");
  EXPECT_EQ(esc.first, 2) << esc.second;
  EXPECT_EQ(esc.second.find('\x1b'), std::string::npos) << esc.second;
  EXPECT_NE(esc.second.find("\"ab\\x1b[31mRED\""), std::string::npos) << esc.second;
}

// Values whose arithmetic leaves the range of doubles were found after the
// work (t_end = 1e308: the particles ran, then "t = 1e+308 is not allowed"
// named no key of the scene) or under a name the scene never wrote
// (initial.bodies.x[2], initial.v0, cluster.max_gap, compare.mass_edges). Each
// is refused before any work (the run would be killed at its first progress
// report below), naming the key and where it was set.
TEST(HostileValues, ValuesBeyondTheRangeOfDoublesAreRefusedBeforeAnyWork) {
  const fs::path root = fresh_dir("hostile-ranges");
  const std::string scene =
      "[scene]\nname = \"ranges\"\n[initial]\nN = 2000\n[particles]\nr = 0.5\ndelta = 1e-2\nt_end = 100\n"
      "[continuum]\nsolvers = [\"hopf_lax\"]\ncells = 2000\n[compare]\n[output]\nplots = false\n";
  write_text(root / "scene.toml", scene);
  const Options killed_at_work = with_env({{"SHOCKGAS_FAULT", "compute:1"}});
  for (const std::string set :
       {"particles.t_end=1e308", "initial.L=1e308", "initial.amplitude=1e308", "particles.delta=1e308",
        "compare.min_cluster_particles=9.2e18", "particles.realizations=9.2e18"}) {
    const std::string key = set.substr(0, set.find('='));
    const auto [code, err] = run_child(
        {"run", (root / "scene.toml").string(), "--out", (root / "out").string(), "-q", "--set", set},
        killed_at_work);
    EXPECT_EQ(code, 2) << set << "\n" << err;
    EXPECT_NE(err.find("--set " + set + ": " + key + " = "), std::string::npos) << err;
  }
}

// A continuum solve obeys the run's wall limit as a realization does (finding:
// t_end = 9.2e18 with max_wall_seconds = 5 never ended, deaf to SIGTERM: the
// solver reported progress only every 1% of t_end).
TEST(HostileValues, AContinuumSolveObeysTheWallLimit) {
  const fs::path root = fresh_dir("hostile-wall");
  write_text(root / "scene.toml",
             "[scene]\nname = \"wall\"\n[initial]\nN = 2000\n[particles]\nr = 0.5\ndelta = 1e-2\n"
             "t_end = 9.2e18\nmax_wall_seconds = 1\n[continuum]\nsolvers = [\"godunov\"]\ncells = 2000\n"
             "[output]\nplots = false\n");
  Child child({"run", (root / "scene.toml").string(), "--out", (root / "out").string(), "-q"});
  for (int i = 0; i < 6000 && process_alive(child.pid()); ++i)  // at most 10 minutes, then it hangs
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  if (process_alive(child.pid())) kill(child.pid(), SIGKILL);
  EXPECT_EQ(child.wait(), 1) << child.err();
  EXPECT_NE(child.err().find("when the wall limit particles.max_wall_seconds = 1 s ran out"),
            std::string::npos)
      << child.err();
  EXPECT_FALSE(fs::exists(root / "out"));
}

}  // namespace
}  // namespace shockgas::app
