// Shards that merge: a run's realizations computed in slices (`shockgas run
// --realizations A:B`), merged by `shockgas merge` into the result one run of
// all of them writes, bit for bit; and the shards a merge refuses.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "run_command.hpp"
#include "run_comparison.hpp"
#include "shockgas/app/files/manifest.hpp"
#include "shockgas/app/output/hdf5_file.hpp"
#include "shockgas/app/output/layout_version.hpp"

namespace shockgas::app {
namespace {

namespace fs = std::filesystem;

using testing_support::run;

// Ten realizations with every record a merge must carry: series, histogram,
// a snapshot and the final state of realization 0, the continuum and the
// comparison (run at merge time).
const char* kScene =
    "[initial]\nN = 300\n[particles]\nr = 0.5\nt_end = 20\nsamples = 8\nrealizations = 10\n"
    "histogram_bins = 12\nsnapshots = [5]\n[continuum]\nsolvers = [\"hopf_lax\"]\ncells = 300\n[compare]\n"
    "[output]\nplots = false\n";

const char* kSweep =
    "[initial]\nN = 200\n[particles]\nt_end = 10\nsamples = 6\nrealizations = 4\n"
    "[sweep]\nvariants = [\"particles.r=0.2\", \"particles.r=0.8\"]\n[output]\nplots = false\n";

// An animation: realization 0 also stops at the frame times, every realization
// runs with them, and the frames are drawn at merge time.
const char* kAnimated =
    "[initial]\nN = 200\n[particles]\nr = 0.5\nt_end = 10\nsamples = 6\nrealizations = 4\n"
    "[continuum]\nsolvers = [\"hopf_lax\"]\ncells = 200\n"
    "[output]\nplots = false\nanimation = true\nanimation_frames = 5\n";

class Shards : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = testing_support::fresh_test_directory("shockgas-test-shards-");
    std::ofstream(dir_ / "scene.toml") << kScene;
    std::ofstream(dir_ / "sweep.toml") << kSweep;
    std::ofstream(dir_ / "animated.toml") << kAnimated;
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  int shard(const std::string& scene, const std::string& option, const std::string& slice,
            const std::string& out, std::vector<std::string> extra = {}) {
    std::vector<std::string> args{"run", path(scene), option, slice, "--out", path(out), "-q"};
    args.insert(args.end(), extra.begin(), extra.end());
    return run(args);
  }
  // Runs the merge; returns its exit code and keeps what it said.
  int merge(std::vector<std::string> shards, const std::string& out) {
    std::vector<std::string> args{"merge"};
    for (const auto& s : shards) args.push_back(path(s));
    args.insert(args.end(), {"--out", path(out), "-q"});
    return testing_support::run_saying(std::move(args), said_);
  }
  fs::path dir_;
  std::string said_;
};

TEST_F(Shards, ThreeShardsMergeToOneRunOfAll) {
  ASSERT_EQ(run({"run", path("scene.toml"), "--out", path("whole"), "-q"}), 0);
  ASSERT_EQ(shard("scene.toml", "--realizations", "0:3", "s0"), 0);
  ASSERT_EQ(shard("scene.toml", "--realizations", "3:7", "s1"), 0);
  ASSERT_EQ(shard("scene.toml", "--realizations", "7:10", "s2"), 0);
  ASSERT_EQ(merge({"s2", "s0", "s1"}, "merged"), 0) << said_;
  EXPECT_EQ(testing::result_differences(dir_ / "whole", dir_ / "merged"), std::vector<std::string>{});
  EXPECT_TRUE(fs::exists(dir_ / "merged" / "report.md"));
  EXPECT_EQ(testing::read_json(dir_ / "merged" / "summary.json")["parallel"]["shards"], 3);
}

TEST_F(Shards, OnlyTheShardOfRealizationZeroCarriesStates) {
  ASSERT_EQ(shard("scene.toml", "--realizations", "0:2", "s0"), 0);
  ASSERT_EQ(shard("scene.toml", "--realizations", "2:4", "s1"), 0);
  auto paths = [&](const std::string& s) {
    std::vector<std::string> p;
    for (const auto& d : Hdf5File::open(path(s + "/result.h5")).datasets()) p.push_back(d.path);
    return p;
  };
  auto has = [](const std::vector<std::string>& p, const std::string& x) {
    return std::find(p.begin(), p.end(), x) != p.end();
  };
  const auto first = paths("s0"), second = paths("s1");
  EXPECT_TRUE(has(first, "/shard/0/0/final/x"));
  EXPECT_TRUE(has(first, "/shard/0/0/snapshots/0/x"));
  EXPECT_TRUE(has(first, "/shard/0/1/series/T"));
  EXPECT_FALSE(has(first, "/shard/0/1/final/x"));
  EXPECT_TRUE(has(second, "/shard/0/2/series/T"));
  for (const auto& p : second) EXPECT_EQ(p.find("final"), std::string::npos) << p;
}

TEST_F(Shards, ASweepShardedByVariantAndRealizationMerges) {
  ASSERT_EQ(run({"run", path("sweep.toml"), "--out", path("whole"), "-q"}), 0);
  ASSERT_EQ(shard("sweep.toml", "--variants", "0:1", "v0"), 0);
  ASSERT_EQ(shard("sweep.toml", "--variants", "1:2", "v1a", {"--realizations", "0:1"}), 0);
  ASSERT_EQ(shard("sweep.toml", "--variants", "1:2", "v1b", {"--realizations", "1:4"}), 0);
  ASSERT_EQ(merge({"v0", "v1a", "v1b"}, "merged"), 0) << said_;
  EXPECT_EQ(testing::result_differences(dir_ / "whole", dir_ / "merged"), std::vector<std::string>{});
}

TEST_F(Shards, AnAnimatedRunMergesWithItsFrames) {
  ASSERT_EQ(run({"run", path("animated.toml"), "--out", path("whole"), "-q"}), 0);
  ASSERT_EQ(shard("animated.toml", "--realizations", "0:1", "s0"), 0);
  ASSERT_EQ(shard("animated.toml", "--realizations", "1:4", "s1"), 0);
  ASSERT_EQ(merge({"s0", "s1"}, "merged"), 0) << said_;
  EXPECT_EQ(testing::result_differences(dir_ / "whole", dir_ / "merged"), std::vector<std::string>{});
  bool has_frames = false;
  for (const auto& d : Hdf5File::open(path("merged/result.h5")).datasets())
    has_frames |= d.path == "/animation/t";
  EXPECT_TRUE(has_frames);
}

TEST_F(Shards, OverlappingSlicesAreRefused) {
  ASSERT_EQ(shard("scene.toml", "--realizations", "0:5", "a"), 0);
  ASSERT_EQ(shard("scene.toml", "--realizations", "3:10", "b"), 0);
  EXPECT_EQ(merge({"a", "b"}, "merged"), 2);
  EXPECT_NE(said_.find("both hold 3:5"), std::string::npos) << said_;
  EXPECT_FALSE(fs::exists(dir_ / "merged"));
}

TEST_F(Shards, MissingSlicesAreRefusedAndListed) {
  ASSERT_EQ(shard("scene.toml", "--realizations", "1:3", "a"), 0);
  ASSERT_EQ(shard("scene.toml", "--realizations", "5:7", "b"), 0);
  EXPECT_EQ(merge({"a", "b"}, "merged"), 2);
  EXPECT_NE(said_.find("missing realizations 0:1 3:5 7:10"), std::string::npos) << said_;
  EXPECT_FALSE(fs::exists(dir_ / "merged"));
}

TEST_F(Shards, ShardsOfAnotherSceneAreRefused) {
  ASSERT_EQ(shard("scene.toml", "--realizations", "0:5", "a"), 0);
  ASSERT_EQ(shard("scene.toml", "--realizations", "5:10", "b", {"--set", "particles.r=0.6"}), 0);
  EXPECT_EQ(merge({"a", "b"}, "merged"), 2);
  EXPECT_NE(said_.find("shards of one scene"), std::string::npos) << said_;
  EXPECT_NE(said_.find("r = 0.6"), std::string::npos) << said_;
  EXPECT_FALSE(fs::exists(dir_ / "merged"));
}

TEST_F(Shards, ShardsOfAnotherBuildAreRefused) {
  ASSERT_EQ(shard("scene.toml", "--realizations", "0:5", "a"), 0);
  ASSERT_EQ(shard("scene.toml", "--realizations", "5:10", "b"), 0);
  // As that build wrote it: close() writes the file's own checksum again, so
  // the merge refuses the build and not a damaged file.
  Hdf5File other_build = Hdf5File::update(path("b/result.h5"));
  other_build.set_attribute("/", "git_commit", "0000000");
  other_build.close();
  write_manifest(dir_ / "b", "scene");
  EXPECT_EQ(merge({"a", "b"}, "merged"), 2);
  EXPECT_NE(said_.find("shards written by one build"), std::string::npos) << said_;
  EXPECT_FALSE(fs::exists(dir_ / "merged"));
}

// A shard of an older major layout holds other quantities under the same
// paths (3.0: /particles/n_clusters): refused, not averaged with this build's.
TEST_F(Shards, AShardOfAnotherMajorLayoutIsRefused) {
  ASSERT_EQ(shard("scene.toml", "--realizations", "0:5", "a"), 0);
  ASSERT_EQ(shard("scene.toml", "--realizations", "5:10", "b"), 0);
  Hdf5File older = Hdf5File::update(path("b/result.h5"));
  older.set_attribute("/", "layout_version", std::to_string(kLayoutVersion.major - 1) + ".1");
  older.close();
  write_manifest(dir_ / "b", "scene");
  EXPECT_EQ(merge({"a", "b"}, "merged"), 2);
  EXPECT_NE(said_.find("of layout " + std::to_string(kLayoutVersion.major) + ".x"), std::string::npos)
      << said_;
  EXPECT_NE(said_.find("this one is of layout " + std::to_string(kLayoutVersion.major - 1) + ".1"),
            std::string::npos)
      << said_;
  EXPECT_FALSE(fs::exists(dir_ / "merged"));
}

TEST_F(Shards, DirectoriesThatAreNoShardsAreRefused) {
  ASSERT_EQ(run({"run", path("scene.toml"), "--out", path("whole"), "-q"}), 0);
  EXPECT_EQ(merge({"whole"}, "merged"), 2);
  EXPECT_NE(said_.find("holds a whole run"), std::string::npos) << said_;
  EXPECT_EQ(merge({"nowhere"}, "merged"), 2);
  EXPECT_NE(said_.find("no result.h5"), std::string::npos) << said_;
  EXPECT_EQ(merge({"whole/result.h5"}, "merged"), 2);  // said "no result.h5 in it"
  EXPECT_NE(said_.find("this is a file: give the directory that holds it"), std::string::npos) << said_;
  EXPECT_FALSE(fs::exists(dir_ / "merged"));
  // The refusal of another scene's results says to give --force: merge takes it.
  ASSERT_EQ(shard("scene.toml", "--realizations", "0:10", "all"), 0);
  std::ofstream(dir_ / "other.toml") << "[scene]\nname = \"other\"\n" << kSweep;
  ASSERT_EQ(run({"run", path("other.toml"), "--out", path("theirs"), "-q"}), 0);
  EXPECT_EQ(merge({"all"}, "theirs"), 2);
  EXPECT_NE(said_.find("give --force"), std::string::npos) << said_;
  EXPECT_EQ(run({"merge", path("all"), "--out", path("theirs"), "--force", "-q"}), 0);
}

TEST_F(Shards, SlicesOutsideTheRunAreRefusedBeforeAnyWork) {
  EXPECT_EQ(shard("scene.toml", "--realizations", "5:20", "a"), 2);
  EXPECT_EQ(shard("scene.toml", "--realizations", "7", "b"), 2);
  EXPECT_EQ(shard("scene.toml", "--realizations", "4:4", "c"), 2);
  EXPECT_EQ(shard("scene.toml", "--variants", "0:1", "d"), 2);  // no [sweep]
  EXPECT_EQ(shard("sweep.toml", "--variants", "1:3", "e"), 2);
  for (const char* out : {"a", "b", "c", "d", "e"}) EXPECT_FALSE(fs::exists(dir_ / out)) << out;
}

// A shard carries a manifest of its three files (it had none: `info` could not
// check it, and a merge read a shard with a changed byte as data), so a merge
// refuses a damaged shard before the HDF5 library reads it.
TEST_F(Shards, AShardIsCheckedAgainstItsManifestBeforeItIsMerged) {
  ASSERT_EQ(shard("scene.toml", "--realizations", "0:5", "a"), 0);
  ASSERT_EQ(shard("scene.toml", "--realizations", "5:10", "b"), 0);
  const auto manifest = read_manifest(dir_ / "b");
  ASSERT_TRUE(manifest);
  std::vector<std::string> listed;
  for (const auto& f : manifest->files) listed.push_back(f.path);
  EXPECT_EQ(listed, (std::vector<std::string>{"report.md", "result.h5", "summary.json"}));
  const fs::path file = dir_ / "b" / "result.h5";
  {
    std::fstream f(file, std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(static_cast<std::streamoff>(fs::file_size(file) / 2));
    f.put('\x55');
  }
  EXPECT_EQ(merge({"a", "b"}, "merged"), 2);
  EXPECT_NE(said_.find(file.string() + ": damaged"), std::string::npos) << said_;
  EXPECT_FALSE(fs::exists(dir_ / "merged"));
}

// The merge's output directory is replaced as a whole: it may not be, or hold,
// a shard it merges (merge a b --out a replaced shard a without a word).
TEST_F(Shards, AMergeIntoOneOfItsShardsIsRefused) {
  ASSERT_EQ(shard("scene.toml", "--realizations", "0:5", "in/a"), 0);
  ASSERT_EQ(shard("scene.toml", "--realizations", "5:10", "in/b"), 0);
  for (const std::string out : {"in/a", "in"}) {
    EXPECT_EQ(merge({"in/a", "in/b"}, out), 2) << out;
    EXPECT_NE(said_.find("a directory that neither is nor holds a shard being merged"), std::string::npos)
        << said_;
  }
  const auto a = read_manifest(dir_ / "in" / "a");
  ASSERT_TRUE(a);
  EXPECT_EQ(a->scene, "scene");  // still the shard
  EXPECT_EQ(merge({"in/a", "in/b"}, "merged"), 0) << said_;
}

}  // namespace
}  // namespace shockgas::app
