// `shockgas stats` (shockgas/app/jobs/statistics_run.hpp): the shock statistics
// of ten shards equal those of their merged run, bit for bit, and hold the exact
// laws; what it cannot use it refuses with exit 2, naming the directory.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <sstream>
#include <string>

#include "child_run.hpp"
#include "run_dir_checks.hpp"

namespace shockgas::app {
namespace {

namespace fs = std::filesystem;
using namespace testing;

// The exact sticky gas from white noise: 10 shards of 3 realizations of N = 10^4
// at t = 1000 (a = 110 particles: the exact laws hold, docs/statistics.md).
const char* kWhiteNoise =
    "[scene]\nname = \"white-noise\"\n[initial]\nN = 10000\nvelocities = \"uniform\"\nseed = 3\n"
    "[particles]\nr = 0\nsolver = \"hull\"\nt_end = 1000\nsamples = 4\nrealizations = 30\n";

class StatisticsCommand : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    root_ = fresh_dir("statistics-command");
    write_text(root_ / "wn.toml", kWhiteNoise);
    for (int k = 0; k < 10; ++k) {
      const std::string slice = std::to_string(3 * k) + ":" + std::to_string(3 * k + 3);
      const fs::path shard = root_ / ("shard-" + std::to_string(k));
      ASSERT_EQ(run_child({"run", (root_ / "wn.toml").string(), "--realizations", slice, "--out",
                           shard.string(), "-q", "--no-plots"})
                    .first,
                0);
      shards_.push_back(shard.string());
    }
    std::vector<std::string> merge = {"merge"};
    merge.insert(merge.end(), shards_.begin(), shards_.end());
    merge.insert(merge.end(), {"--out", (root_ / "merged").string(), "-q", "--no-plots"});
    ASSERT_EQ(run_child(merge).first, 0);
  }
  static std::pair<int, std::string> stats(std::vector<std::string> dirs, const std::string& out) {
    std::vector<std::string> args = {"stats"};
    args.insert(args.end(), dirs.begin(), dirs.end());
    args.insert(args.end(), {"--out", (root_ / out).string(), "-q", "--no-plots"});
    return run_child(args);
  }
  // statistics.csv's single-number rows (count, *_p_value, ...) by name.
  static std::map<std::string, double> numbers(const std::string& out) {
    std::map<std::string, double> n;
    std::istringstream in(read_text(root_ / out / "statistics.csv"));
    for (std::string line; std::getline(in, line);) {
      const std::string name = line.substr(0, line.find(','));
      if (line.find(",,,") == name.size()) n[name] = std::stod(line.substr(name.size() + 3));
    }
    return n;
  }
  static inline fs::path root_;
  static inline std::vector<std::string> shards_;
};

TEST_F(StatisticsCommand, TenShardsGiveTheStatisticsOfTheirMergedRun) {
  ASSERT_EQ(stats(shards_, "of-shards").first, 0);
  ASSERT_EQ(stats({(root_ / "merged").string()}, "of-merged").first, 0);
  EXPECT_EQ(read_text(root_ / "of-shards" / "statistics.csv"),
            read_text(root_ / "of-merged" / "statistics.csv"));
  EXPECT_EQ(read_text(root_ / "of-shards" / "statistics.md"),
            read_text(root_ / "of-merged" / "statistics.md"));
  EXPECT_TRUE(fs::is_regular_file(root_ / "of-shards" / "statistics.h5"));
  // Its manifest names the statistics run ("<scene>-stats"), the file the scene
  // it measures: `info` reads it as sound (it said "not as its manifest.json records").
  const auto [code, err] = run_child({"info", (root_ / "of-shards" / "statistics.h5").string()});
  EXPECT_EQ(code, 0) << err;
}

TEST_F(StatisticsCommand, TheShardsHoldTheExactLaws) {
  ASSERT_EQ(stats(shards_, "laws").first, 0);
  const auto n = numbers("laws");
  EXPECT_EQ(n.at("realizations"), 30);
  // The acceptance level: a law that holds is rejected one time in a hundred.
  EXPECT_GT(n.at("mass_p_value"), 0.01);
  EXPECT_GT(n.at("velocity_p_value"), 0.01);
}

TEST_F(StatisticsCommand, ARealizationTwiceIsRefused) {
  const auto [code, err] = stats({(root_ / "merged").string(), shards_.front()}, "twice");
  EXPECT_EQ(code, 2) << err;
  EXPECT_NE(err.find("both hold realization 0 of seed 3"), std::string::npos) << err;
  EXPECT_FALSE(fs::exists(root_ / "twice"));
}

TEST_F(StatisticsCommand, AnOutputInOrAroundASourceIsRefused) {
  for (const fs::path& out : {fs::path(shards_.front()) / "stats", root_}) {
    const auto [code, err] = run_child({"stats", shards_.front(), "--out", out.string(), "-q", "--no-plots"});
    EXPECT_EQ(code, 2) << err;
    EXPECT_NE(err.find("--out"), std::string::npos) << err;
  }
  EXPECT_FALSE(fs::exists(fs::path(shards_.front()) / "stats"));
}

TEST_F(StatisticsCommand, AnotherGasIsRefusedNamingTheKey) {
  const fs::path other = root_ / "older";
  ASSERT_EQ(run_child({"run", (root_ / "wn.toml").string(), "--set", "particles.t_end=2000", "--set",
                       "initial.seed=4", "--set", "particles.realizations=2", "--out", other.string(), "-q",
                       "--no-plots"})
                .first,
            0);
  const auto [code, err] = stats({(root_ / "merged").string(), other.string()}, "mixed");
  EXPECT_EQ(code, 2) << err;
  EXPECT_NE(err.find("t_end"), std::string::npos) << err;
}

TEST_F(StatisticsCommand, OtherSeedsAreMoreRealizations) {
  const fs::path other = root_ / "seed-4";
  ASSERT_EQ(run_child({"run", (root_ / "wn.toml").string(), "--set", "initial.seed=4", "--set",
                       "particles.realizations=2", "--out", other.string(), "-q", "--no-plots"})
                .first,
            0);
  ASSERT_EQ(stats({(root_ / "merged").string(), other.string()}, "seeds").first, 0);
  EXPECT_EQ(numbers("seeds").at("realizations"), 32);
}

TEST_F(StatisticsCommand, ARunWithoutFinalClustersIsRefusedWithTheKey) {
  const fs::path none = root_ / "none";
  ASSERT_EQ(run_child({"run", (root_ / "wn.toml").string(), "--set", "particles.final_clusters=never",
                       "--set", "particles.realizations=1", "--out", none.string(), "-q", "--no-plots"})
                .first,
            0);
  const auto [code, err] = stats({none.string()}, "none-stats");
  EXPECT_EQ(code, 2) << err;
  EXPECT_NE(err.find("particles.final_clusters=always"), std::string::npos) << err;
  const auto [missing, why] = stats({(root_ / "no-such").string()}, "missing-stats");
  EXPECT_EQ(missing, 2) << why;
  const auto [file, said] = stats({(fs::path(shards_.front()) / "result.h5").string()}, "file-stats");
  EXPECT_EQ(file, 2) << said;
  EXPECT_NE(said.find("this is a file"), std::string::npos) << said;
}

}  // namespace
}  // namespace shockgas::app
