// Every command that writes a directory goes through one mechanism, taken
// before any work (findings of a hostile pass: the lock file followed links
// and wrote a process number into the file they named; a shard overwrote
// another scene's results in place, stale pictures kept; the lock was taken
// after the particles, so two runs into one directory both computed and
// failed, or one replaced the other; a killed run left its directory behind,
// or a states file inside earlier results; an immutable directory was found
// only after the whole computation).
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "child_run.hpp"
#include "run_dir_checks.hpp"

namespace shockgas::app {
namespace {

using namespace testing;

// A scene that computes for a while (its particles report progress often).
const char* kLong =
    "[scene]\nname = \"long\"\n[initial]\nN = 20000\n[particles]\nr = 0.5\nt_end = 200\n"
    "realizations = 2\nsnapshots = [0.5, 1.0]\n[output]\nplots = false\n";

struct Place {
  fs::path root, a, long_scene, out;
};

Place place(const std::string& name) {
  Place p;
  p.root = fresh_dir(name);
  p.a = p.root / "alpha.toml";
  p.long_scene = p.root / "long.toml";
  write_text(p.a, std::string(kSceneA) + "[output]\nplots = false\n");
  write_text(p.long_scene, kLong);
  p.out = p.root / "o";
  return p;
}

// The lock file in place of a link or a hard link to a file: the file is
// never written, the run is refused (exit 2) before any work.
TEST(DirectoryRules, TheLockFileNeverFollowsALink) {
  const Place p = place("rules-lock-link");
  write_text(p.root / "precious.txt", "precious\n");
  fs::create_symlink("precious.txt", p.root / ".o.lock");
  auto [code, err] = run_child({"run", p.a.string(), "--out", p.out.string(), "-q"});
  EXPECT_EQ(code, 2) << err;
  EXPECT_NE(err.find("a symbolic link"), std::string::npos) << err;
  EXPECT_EQ(read_text(p.root / "precious.txt"), "precious\n");
  EXPECT_TRUE(fs::is_symlink(p.root / ".o.lock"));
  fs::remove(p.root / ".o.lock");
  fs::create_hard_link(p.root / "precious.txt", p.root / ".o.lock");
  std::tie(code, err) = run_child({"run", p.a.string(), "--out", p.out.string(), "-q"});
  EXPECT_EQ(code, 2) << err;
  EXPECT_NE(err.find("hard link"), std::string::npos) << err;
  EXPECT_EQ(read_text(p.root / "precious.txt"), "precious\n");
  fs::remove(p.root / ".o.lock");
  write_text(p.root / ".o.lock", "my notes\n");  // a foreign file in its place
  std::tie(code, err) = run_child({"run", p.a.string(), "--out", p.out.string(), "-q"});
  EXPECT_EQ(code, 2) << err;
  EXPECT_EQ(read_text(p.root / ".o.lock"), "my notes\n");
  EXPECT_FALSE(fs::exists(p.out));
}

// A temporary file of a write in place (the manifest of a sweep, brought up
// to date by `shockgas animate` of a variant) is made anew, never written
// through a link left in its place.
TEST(DirectoryRules, ATemporaryFileNeverFollowsALink) {
  const Place p = place("rules-temporary-link");
  write_text(p.root / "sweep.toml", std::string(kSceneA) +
                                        "[sweep]\nvariants = [\"particles.r=0.5\"]\nlabels = [\"half\"]\n"
                                        "[output]\nplots = false\nanimation = true\nanimation_frames = 3\n");
  const fs::path script = p.root / "animation.py";
  write_text(script,
             "import os, sys\nopen(os.path.join(sys.argv[1], 'animation.png'), 'w').write('frame')\n");
  const Options stand_in = with_env({{"SHOCKGAS_ANIMATE_SCRIPT", script.string()}});
  auto [code, err] =
      run_child({"run", (p.root / "sweep.toml").string(), "--out", p.out.string(), "-q"}, stand_in);
  ASSERT_EQ(code, 0) << err;
  write_text(p.root / "precious.txt", "precious\n");
  fs::create_symlink(p.root / "precious.txt", p.out / "manifest.json.partial");
  std::tie(code, err) = run_child({"animate", (p.out / "0-half").string()}, stand_in);
  EXPECT_EQ(code, 0) << err;
  EXPECT_EQ(read_text(p.root / "precious.txt"), "precious\n");
  EXPECT_EQ(whole_run(p.out / "0-half", "alpha/half"), "");
}

// A second run into a directory is refused at once (exit 2, naming the
// process that holds it) while the first computes, which then ends whole.
TEST(DirectoryRules, ASecondRunIsRefusedAtOnceWhileTheFirstComputes) {
  const Place p = place("rules-second-run");
  Child first({"run", p.long_scene.string(), "--out", p.out.string(), "-q"},
              with_env({{"SHOCKGAS_FAULT", "compute:1:stop"}}));
  ASSERT_TRUE(first.wait_stopped()) << first.err();
  for (const std::vector<std::string>& second :
       {std::vector<std::string>{"run", p.long_scene.string(), "--out", p.out.string(), "-q"},
        std::vector<std::string>{"run", p.long_scene.string(), "--realizations", "0:1", "--out",
                                 p.out.string(), "-q"},
        std::vector<std::string>{"run", p.a.string(), "--out", p.out.string(), "-q", "--force"}}) {
    const auto [code, err] = run_child(second);
    EXPECT_EQ(code, 2) << err;
    EXPECT_NE(err.find("shockgas process " + std::to_string(first.pid()) + " holds"), std::string::npos)
        << err;
  }
  kill(first.pid(), SIGCONT);
  EXPECT_EQ(first.wait(), 0) << first.err();
  EXPECT_EQ(whole_run(p.out, "long"), "");
  EXPECT_TRUE(leftovers(p.out).empty());
}

// A first run killed while it computes leaves no directory (not even an
// empty one, nor a states file); one killed over earlier results leaves them
// as they were. The next run clears what it left beside them.
TEST(DirectoryRules, AKilledRunLeavesTheDirectoryAsItWas) {
  const Place p = place("rules-killed");
  const Options kill_at_compute = with_env({{"SHOCKGAS_FAULT", "compute:3"}});
  auto [code, err] =
      run_child({"run", p.long_scene.string(), "--out", p.out.string(), "-q"}, kill_at_compute);
  ASSERT_EQ(code, 128 + SIGKILL) << err;
  EXPECT_FALSE(fs::exists(p.out));
  std::tie(code, err) =
      run_child({"run", p.long_scene.string(), "--out", p.out.string(), "-q", "--set", "particles.t_end=2"});
  ASSERT_EQ(code, 0) << err;
  EXPECT_TRUE(leftovers(p.out).empty());
  std::tie(code, err) =
      run_child({"run", p.long_scene.string(), "--out", p.out.string(), "-q"}, kill_at_compute);
  ASSERT_EQ(code, 128 + SIGKILL) << err;
  EXPECT_EQ(whole_run(p.out, "long"), "");
  // A shard killed while it writes its result.h5 leaves nothing in its directory.
  std::tie(code, err) = run_child({"run", p.long_scene.string(), "--realizations", "0:1", "--out",
                                   p.out.string(), "-q", "--set", "particles.t_end=2"},
                                  with_env({{"SHOCKGAS_FAULT", "write:result.h5:2"}}));
  ASSERT_EQ(code, 128 + SIGKILL) << err;
  EXPECT_EQ(whole_run(p.out, "long"), "");
}

// A shard goes through the rules of every run directory: another scene's
// results are refused without --force, and replaced as a whole with it (no
// stale report.html of the run it replaced).
TEST(DirectoryRules, AShardFollowsTheRulesOfEveryRunDirectory) {
  const Place p = place("rules-shard");
  auto [code, err] = run_child({"run", p.a.string(), "--out", p.out.string(), "-q"});
  ASSERT_EQ(code, 0) << err;
  const std::vector<std::string> shard = {
      "run",   p.long_scene.string(), "--realizations", "0:1", "--out", p.out.string(), "-q",
      "--set", "particles.t_end=2"};
  std::tie(code, err) = run_child(shard);
  EXPECT_EQ(code, 2) << err;
  EXPECT_NE(err.find("give --force"), std::string::npos) << err;
  EXPECT_EQ(whole_run(p.out, "alpha"), "");
  std::vector<std::string> forced = shard;
  forced.push_back("--force");
  std::tie(code, err) = run_child(forced);
  ASSERT_EQ(code, 0) << err;
  EXPECT_EQ(whole_run(p.out, "long"), "");
  EXPECT_FALSE(fs::exists(p.out / "report.html"));  // a shard writes none; alpha's is gone
}

// A directory that cannot be written is refused before any work (the run
// would otherwise be killed at its first progress report below).
TEST(DirectoryRules, AnImmutableDirectoryIsRefusedBeforeAnyWork) {
  const Place p = place("rules-immutable");
  fs::create_directories(p.root / "frozen");
  if (::geteuid() != 0 ||
      std::system(("chattr +i '" + (p.root / "frozen").string() + "' 2>/dev/null").c_str()) != 0)
    GTEST_SKIP() << "needs root and a file system with the immutable attribute (chattr +i)";
  const auto [code, err] =
      run_child({"run", p.long_scene.string(), "--out", (p.root / "frozen" / "o").string(), "-q"},
                with_env({{"SHOCKGAS_FAULT", "compute:1"}}));
  std::system(("chattr -i '" + (p.root / "frozen").string() + "'").c_str());
  EXPECT_EQ(code, 2) << err;
  EXPECT_NE(err.find("a directory in a place that can be written"), std::string::npos) << err;
}

}  // namespace
}  // namespace shockgas::app
