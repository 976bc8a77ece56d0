// Bad input says what is wrong, where, and writes nothing (findings: odd inputs
// that were accepted -- a directory or an empty file as a scene, a solver named
// twice, a read-only --out; messages that misled -- an unknown --set blamed
// scene.toml:0, spaces around '=' mangled the key, TOML syntax errors read as a
// value not allowed, a deeply nested table gave a 20 kB message, an error in a
// sweep variant was reported as a --set; and a scene name that escaped out/).
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "child_run.hpp"
#include "run_dir_checks.hpp"
#include "shockgas/app/cli/command.hpp"

namespace shockgas::app {
namespace {

using namespace testing;

// Runs the command in this process: {exit code, stderr}.
std::pair<int, std::string> command(std::vector<std::string> args) {
  args.insert(args.begin(), "shockgas");
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  ::testing::internal::CaptureStderr();
  const int code = run_command(static_cast<int>(argv.size()), argv.data());
  return {code, ::testing::internal::GetCapturedStderr()};
}

// Runs a scene text into root/out: nothing may be written on bad input.
std::pair<int, std::string> run_text(const fs::path& root, const std::string& text,
                                     std::vector<std::string> extra = {}) {
  write_text(root / "scene.toml", text);
  std::vector<std::string> args = {
      "run", (root / "scene.toml").string(), "--out", (root / "out").string(), "-q", "--no-plots"};
  args.insert(args.end(), extra.begin(), extra.end());
  auto result = command(args);
  if (result.first == 2) {
    EXPECT_FALSE(fs::exists(root / "out")) << "written on bad input: " << result.second;
    EXPECT_TRUE(leftovers(root / "out").empty());
  }
  return result;
}

void expect_bad(const std::pair<int, std::string>& r, const std::string& says) {
  EXPECT_EQ(r.first, 2) << r.second;
  EXPECT_NE(r.second.find(says), std::string::npos) << "expected: " << says << "\ngot: " << r.second;
}

TEST(InputMessages, ADirectoryOrAnEmptyFileIsNotAScene) {
  const fs::path root = fresh_dir("input-scenefile");
  fs::create_directories(root / "adir");
  write_text(root / "empty.toml", "");
  write_text(root / "comments.toml", "# only a comment\n[initial]\nN = 10\n");
  expect_bad(command({"run", (root / "adir").string(), "-q"}), "adir: a directory");
  expect_bad(command({"run", (root / "empty.toml").string(), "-q"}), "empty.toml: empty");
  expect_bad(command({"run", (root / "comments.toml").string(), "-q"}), "comments.toml: runs nothing");
  expect_bad(command({"run", (root / "missing.toml").string(), "-q"}), "missing.toml: no such file");
}

TEST(InputMessages, ASolverNamedTwiceIsRefusedAtItsLine) {
  const fs::path root = fresh_dir("input-twice");
  expect_bad(run_text(root, std::string(kSceneA) + "[output]\nplots = false\n",
                      {"--set", "continuum.solvers=[\"godunov\", \"godunov\"]"}),
             "continuum.solvers = \"godunov\" is not allowed; allowed: each solver once");
}

TEST(InputMessages, ABadBodiesFileWritesNothing) {
  const fs::path root = fresh_dir("input-bodies");
  write_text(root / "bodies.txt", "0 1\n1 x\n2 0.5\n");
  expect_bad(
      run_text(root, "[initial]\nvelocities = \"file\"\nfile = \"bodies.txt\"\n[particles]\nt_end = 1\n"),
      "initial.file");
  // A word or a fourth number after x v [m] was dropped without a word, and a
  // line that did not start with a number (a header, nan, 1e500) was skipped.
  for (const char* line : {"0 1 junk\n", "0 1 2 3\n", "x v m\n0 1\n", "nan 2\n", "1e500 0\n"}) {
    write_text(root / "bodies.txt", std::string(line) + "1 0\n2 -1\n");
    expect_bad(run_text(root,
                        "[initial]\nvelocities = \"file\"\nfile = \"bodies.txt\"\nN = 3\n[particles]\n"
                        "t_end = 1\ngeometry = \"line\"\n"),
               "bodies.txt:1: initial.file");
  }
}

// The file's bodies are the run's: initial.N must count them (finding: a
// 3-body file ran 3 bodies with summary.json saying N = 2, and a ring's length
// L = N came from the scene's N, not the file).
TEST(InputMessages, ABodiesFileMustHoldInitialNBodies) {
  const fs::path root = fresh_dir("input-bodies-count");
  write_text(root / "bodies.txt", "0 1\n1 0\n2 -1\n");
  const std::string scene =
      "[initial]\nvelocities = \"file\"\nfile = \"bodies.txt\"\n[particles]\nt_end = 1\n"
      "geometry = \"line\"\n[output]\nplots = false\n";
  for (const char* N : {"initial.N=2", "initial.N=4"})
    expect_bad(run_text(root, scene, {"--set", N}),
               "is not allowed; allowed: the number of bodies in initial.file (3 in ");
  EXPECT_EQ(run_text(root, scene, {"--set", "initial.N=3"}).first, 0);
  // and the summary says where the positions came from (it said "lattice")
  EXPECT_NE(read_text(root / "out" / "summary.json").find("\"positions\": \"file\""), std::string::npos);
}

TEST(InputMessages, ASpaceTimeRecordTooLargeWritesNothingAndNamesItsLine) {
  const fs::path root = fresh_dir("input-spacetime");
  expect_bad(run_text(root, "[initial]\nN = 200000\n[particles]\nt_end = 1\nspacetime = true\n"),
             "scene.toml:5: particles.spacetime");
}

TEST(InputMessages, AnUnknownTableInASetNamesTheSet) {
  const fs::path root = fresh_dir("input-unknown");
  const auto r = run_text(root, kSceneA, {"--set", "unknown.key=3"});
  expect_bad(r, "--set unknown.key=3: unknown.key = 3 is not allowed");
  EXPECT_EQ(r.second.find(":0:"), std::string::npos) << r.second;
}

TEST(InputMessages, SpacesAroundTheEqualsSignOfASetAreAllowed) {
  const fs::path root = fresh_dir("input-spaces");
  const auto [code, err] =
      run_text(root, kSceneA, {"--set", "particles.r = 0.3", "--set", "particles.nope = 1"});
  expect_bad({code, err}, "--set particles.nope = 1: particles.nope = 1 is not allowed");
  EXPECT_EQ(run_text(root, kSceneA, {"--set", "particles.r = 0.3"}).first, 0);
  EXPECT_NE(read_text(root / "out" / "summary.json").find("\"r\": 0.3"), std::string::npos);
}

TEST(InputMessages, ANegativeCountSaysTheRule) {
  expect_bad(run_text(fresh_dir("input-negative"), kSceneA, {"--set", "initial.N=-5"}),
             "initial.N = -5 is not allowed; allowed: an integer >= 2");
}

TEST(InputMessages, ATomlSyntaxErrorSaysSo) {
  expect_bad(run_text(fresh_dir("input-syntax"), "[particles\nr = 0.5\n"),
             "scene.toml:1:11: TOML syntax error: ");
}

TEST(InputMessages, ADeeplyNestedTableGivesAShortMessage) {
  const fs::path root = fresh_dir("input-deep");
  std::string dotted = "a";
  for (int i = 0; i < 10000; ++i) dotted += ".a";
  std::string headers;
  for (int i = 1; i <= 2000; ++i) headers += "[" + dotted.substr(0, 2 * i - 1) + "]\n";
  for (const std::string& text : {"[initial]\n" + dotted + " = 1\n", headers}) {
    const auto [code, err] = run_text(root, text);
    EXPECT_EQ(code, 2);
    EXPECT_LT(err.size(), 600u) << err.substr(0, 600);
  }
}

TEST(InputMessages, AnErrorInASweepVariantNamesTheVariant) {
  const fs::path root = fresh_dir("input-sweep");
  const auto r =
      run_text(root, std::string(kSceneA) + "[sweep]\nvariants = [\"particles.r=0.5\", \"particles.r=2\"]\n");
  expect_bad(r, "scene.toml:14 (sweep variant 2: particles.r=2): particles.r = 2 is not allowed");
  EXPECT_EQ(r.second.find("--set"), std::string::npos) << r.second;
}

TEST(InputMessages, TheSceneNameIsANameNotAPath) {
  const fs::path root = fresh_dir("input-name");
  fs::create_directories(root / "a" / "b");
  const std::string body = "[initial]\nN = 100\n[particles]\nt_end = 1\n[output]\nplots = false\n";
  for (const std::string name :
       {"../../escape", "/tmp/absolute", "a/b", ".hidden", "bell\\u0007", "back\\\\slash"}) {
    write_text(root / "scene.toml", "[scene]\nname = \"" + name + "\"\n" + body);
    const auto [code, err] =
        run_child({"run", (root / "scene.toml").string(), "-q"}, in_dir(root / "a" / "b"));
    EXPECT_EQ(code, 2) << name << "\n" << err;
    EXPECT_NE(err.find("scene.name"), std::string::npos) << err;
  }
  EXPECT_FALSE(fs::exists(root / "escape"));
  EXPECT_FALSE(fs::exists(root / "a" / "b" / "out"));
  // A file whose name is not a plain name must set [scene] name.
  write_text(root / ".toml", body);
  expect_bad(command({"run", (root / ".toml").string(), "-q"}), "set [scene] name");
  // A plain name runs into out/<name>.
  write_text(root / "scene.toml", "[scene]\nname = \"plain name\"\n" + body);
  EXPECT_EQ(run_child({"run", (root / "scene.toml").string(), "-q"}, in_dir(root / "a" / "b")).first, 0);
  EXPECT_EQ(whole_run(root / "a" / "b" / "out" / "plain name", "plain name"), "");
}

// --out "" names no directory (finding: run wrote into its default out/NAME,
// bench refused it as the root directory).
TEST(InputMessages, AnEmptyOutputDirectoryIsRefusedByEveryCommand) {
  const fs::path root = fresh_dir("input-empty-out");
  const std::string scene = (fs::path(SHOCKGAS_SOURCE_DIR) / "data/scenes/default.toml").string();
  const std::vector<std::vector<std::string>> commands = {
      {"run", scene}, {"merge", "a", "b"}, {"bench"}, {"tail", "--N", "100"}};
  for (const auto& args : commands) {
    std::vector<std::string> with_out = args;
    with_out.insert(with_out.end(), {"--out", "", "-q"});
    const auto [code, err] = run_child(with_out, in_dir(root));
    EXPECT_EQ(code, 2) << args.front() << "\n" << err;
    EXPECT_NE(err.find("--out: \"\" is not allowed; allowed: a directory name (not empty)"),
              std::string::npos)
        << args.front() << "\n"
        << err;
  }
  EXPECT_TRUE(fs::is_empty(root));
}

}  // namespace
}  // namespace shockgas::app
