// Checkpoints (shockgas/app/records/checkpoint.hpp): the file carries the finished
// realizations' records exactly; a resumed run that keeps them equals the
// uninterrupted run bit for bit; a damaged checkpoint, one of another build
// and a scene that is not the checkpoint's are refused with exit 2, the
// checkpoint left as it was and nothing written. (Realizations saved while
// they ran: test_running_states.cpp. Stopping a run by SIGKILL and SIGTERM in
// a child process: tests/checkpoint.cmake.)
#include <gtest/gtest.h>

#include "app/checkpoint_fixture.hpp"
#include "shockgas/app/cli/info.hpp"
#include "shockgas/app/input/scene_parser.hpp"

namespace shockgas::app {
namespace {

TEST_F(Checkpoints, TheFileCarriesTheRecordsExactly) {
  const Scene scene = load_scene(path("scene.toml"));
  const Checkpoint written = make_checkpoint(scene, "2:5", "", records(scene, {2, 0, 4}));
  write_checkpoint(path("run"), written);
  const Checkpoint back = read_checkpoint(path("run"));
  EXPECT_EQ(back.scene_text, scene.text);
  EXPECT_EQ(back.resolved, resolved_scene_text(scene));
  EXPECT_EQ(back.realizations, "2:5");
  ASSERT_EQ(back.records.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) EXPECT_EQ(encode(back.records[i]), encode(written.records[i])) << i;
  for (const auto& entry : fs::directory_iterator(path("run")))  // no temporary file left beside it
    EXPECT_EQ(entry.path().filename(), "checkpoint.bin");
}

TEST_F(Checkpoints, AResumedRunEqualsTheUninterruptedOne) {
  ASSERT_EQ(command({"run", path("scene.toml"), "--out", path("whole"), "-q"}), 0) << said_;
  interrupted_run("resumed", {3, 0, 1});
  ASSERT_EQ(command({"run", "--resume", path("resumed"), "-q"}), 0) << said_;
  EXPECT_NE(said_.find("3 of 5 realizations kept from the checkpoint"), std::string::npos) << said_;
  EXPECT_FALSE(fs::exists(checkpoint_path(path("resumed"))));  // the result holds it all
  const auto differences = testing::result_differences(path("whole"), path("resumed"));
  EXPECT_TRUE(differences.empty()) << differences.front();
}

// A resumed run's wall time counts what its interrupted parts spent (the
// checkpoint's seconds), so that its rate divides all the collisions by all the
// time spent on them. (Found: 150 M/s reported after a resume, 53 M/s without.)
TEST_F(Checkpoints, AResumedRunCountsTheTimeItsInterruptedPartsSpent) {
  const Scene scene = load_scene(path("scene.toml"));
  Checkpoint c = make_checkpoint(scene, "", "", records(scene, {1, 2}));
  c.seconds = 1000;
  write_checkpoint(path("resumed"), c);
  const auto started = std::chrono::steady_clock::now();
  ASSERT_EQ(command({"run", "--resume", path("resumed"), "-q"}), 0) << said_;
  const double took = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  const auto summary = nlohmann::json::parse(bytes_of(fs::path(path("resumed")) / "summary.json"));
  const double wall = summary["particles"]["wall_seconds"].get<double>();
  EXPECT_GE(wall, 1000.0);
  EXPECT_LE(wall, 1000.0 + took);
  const double collisions = summary["particles"]["collisions"].get<double>();
  EXPECT_DOUBLE_EQ(summary["particles"]["collisions_per_second"].get<double>(), collisions / wall);
}

TEST_F(Checkpoints, ARunThatEndsLeavesNoCheckpoint) {
  ASSERT_EQ(command({"run", path("scene.toml"), "--out", path("run"), "-q", "--set",
                     "output.checkpoint_minutes=1e-4"}),
            0)
      << said_;
  EXPECT_TRUE(fs::exists(path("run/result.h5")));
  EXPECT_FALSE(fs::exists(checkpoint_path(path("run"))));
}

// A directory that holds only an interrupted run's checkpoint is refused to
// another scene (finding: any command replaced it, and the work was lost
// without a word); the same scene may start afresh over it.
TEST_F(Checkpoints, AnotherScenesRunDoesNotReplaceAnInterruptedRun) {
  fs::create_directories(path("run"));
  interrupted_run("run", {0, 2});
  std::ofstream(path("other.toml")) << "[scene]\nname = \"other\"\n" << kScene;
  EXPECT_EQ(command({"run", path("other.toml"), "--out", path("run"), "-q"}), 2) << said_;
  EXPECT_NE(said_.find("holds an interrupted run's checkpoint; continue with: shockgas run --resume"),
            std::string::npos)
      << said_;
  EXPECT_TRUE(fs::exists(checkpoint_path(path("run"))));
  EXPECT_EQ(command({"run", path("scene.toml"), "--out", path("run"), "-q"}), 0) << said_;
}

// `info` on a stopped run's directory says how far its checkpoint got and how
// to continue it (finding of the paper's long runs: it said only that the
// directory holds no result.h5); a damaged checkpoint is an input error there too.
TEST_F(Checkpoints, InfoSaysHowFarAStoppedRunGot) {
  interrupted_run("run", {0, 2});
  EXPECT_EQ(command({"info", path("run")}), 0) << said_;
  std::ostringstream out;
  print_info(path("run"), out);
  const std::string text = out.str();
  EXPECT_NE(text.find("a run stopped before its result was written"), std::string::npos) << text;
  EXPECT_NE(text.find("holds 2 of the 5 realizations finished"), std::string::npos) << text;
  EXPECT_NE(text.find("continue with: shockgas run --resume " + path("run")), std::string::npos) << text;
  std::string bytes = bytes_of(checkpoint_path(path("run")));
  bytes[bytes.size() / 2] ^= 0x10;
  std::ofstream(checkpoint_path(path("run")), std::ios::binary) << bytes;
  EXPECT_EQ(command({"info", path("run")}), 2) << said_;
  EXPECT_NE(said_.find("damaged"), std::string::npos) << said_;
  EXPECT_NE(said_.find("RESULT = "), std::string::npos) << said_;  // what info was given, not --resume
}

TEST_F(Checkpoints, ADamagedCheckpointIsRefusedAndKept) {
  interrupted_run("run", {0, 1});
  std::string bytes = bytes_of(checkpoint_path(path("run")));
  bytes[bytes.size() / 2] ^= 0x10;  // one bit of a record
  std::ofstream(checkpoint_path(path("run")), std::ios::binary) << bytes;
  EXPECT_EQ(command({"run", "--resume", path("run"), "-q"}), 2);
  EXPECT_NE(said_.find("damaged: its checksum does not match"), std::string::npos) << said_;
  EXPECT_EQ(bytes_of(checkpoint_path(path("run"))), bytes);
  EXPECT_FALSE(fs::exists(path("run/result.h5")));
}

TEST_F(Checkpoints, ATruncatedFileOrAnotherFileIsRefused) {
  interrupted_run("run", {0});
  const std::string bytes = bytes_of(checkpoint_path(path("run")));
  std::ofstream(checkpoint_path(path("run")), std::ios::binary) << bytes.substr(0, bytes.size() / 3);
  EXPECT_THROW(read_checkpoint(path("run")), InputError);
  std::ofstream(checkpoint_path(path("run")), std::ios::binary) << kScene;
  try {
    read_checkpoint(path("run"));
    ADD_FAILURE() << "a scene file read as a checkpoint";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("not a shockgas checkpoint"), std::string::npos) << e.what();
  }
  EXPECT_EQ(command({"run", "--resume", path("nothing-here"), "-q"}), 2);
  EXPECT_NE(said_.find("does not exist"), std::string::npos) << said_;
}

TEST_F(Checkpoints, ACheckpointOfAnotherBuildIsRefused) {
  const Scene scene = load_scene(path("scene.toml"));
  Checkpoint other = make_checkpoint(scene, "", "", records(scene, {0}));
  other.version = "0.0.1-other";
  write_checkpoint(path("run"), other);
  EXPECT_EQ(command({"run", "--resume", path("run"), "-q"}), 2);
  EXPECT_NE(said_.find("written by shockgas 0.0.1-other"), std::string::npos) << said_;
  EXPECT_TRUE(fs::exists(checkpoint_path(path("run"))));
}

TEST_F(Checkpoints, AnotherSceneIsRefusedAThreadCountIsNot) {
  interrupted_run("run", {0});
  EXPECT_EQ(command({"run", "--resume", path("run"), path("scene.toml"), "-q", "--set", "particles.r=0.6"}),
            2);
  EXPECT_NE(said_.find("differs in `r = 0.6"), std::string::npos) << said_;
  EXPECT_FALSE(fs::exists(path("run/result.h5")));
  EXPECT_EQ(command({"run", "--resume", path("run"), "-q", "--set", "particles.threads=2"}),
            2);  // no scene named
  EXPECT_EQ(
      command({"run", "--resume", path("run"), path("scene.toml"), "-q", "--set", "particles.threads=2"}), 0)
      << said_;
}

TEST_F(Checkpoints, RecordsThatTheRunDoesNotComputeAreRefused) {
  const Scene scene = load_scene(path("scene.toml"));
  std::vector<RealizationRecord> r = records(scene, {0});
  r[0].index = 7;  // the scene has 5 realizations
  write_checkpoint(path("run"), make_checkpoint(scene, "", "", std::move(r)));
  EXPECT_EQ(command({"run", "--resume", path("run"), "-q"}), 2);
  EXPECT_NE(said_.find("realization 7 of ensemble 0, which the run does not compute"), std::string::npos)
      << said_;
}

// Without a comparison, realization 0's states go to DIR/states-0.bin as it
// runs (state_file.hpp), and its record in the checkpoint holds none.
const char* kSceneApart =
    "[initial]\nN = 300\n[particles]\nr = 0.5\nt_end = 15\nsamples = 7\nrealizations = 5\n"
    "histogram_bins = 10\nsnapshots = [4, 9]\n[output]\nplots = false\n";

class CheckpointsWithStatesApart : public Checkpoints {
 protected:
  void SetUp() override {
    Checkpoints::SetUp();
    std::ofstream(path("scene.toml")) << kSceneApart;
  }
  // The checkpoint and state file of a run into `out` killed after realization
  // 0 and `others` finished.
  void interrupted_run(const std::string& out, std::vector<std::uint64_t> others) const {
    const Scene scene = load_scene(path("scene.toml"));
    fs::create_directories(path(out));
    StateFileWriter states(state_file_path(path(out), 0));
    const InitialCondition ic(scene.initial);
    std::vector<RealizationRecord> kept = {
        {0, 0, particles::simulate(ic, 0, particle_params(scene), {}, &states.sink()), true}};
    states.commit();
    for (RealizationRecord& r : records(scene, std::move(others))) kept.push_back(std::move(r));
    write_checkpoint(path(out), make_checkpoint(scene, "", "", std::move(kept)));
  }
};

TEST_F(CheckpointsWithStatesApart, AResumedRunTakesRealizationZeroFromItsStateFile) {
  ASSERT_EQ(command({"run", path("scene.toml"), "--out", path("whole"), "-q"}), 0) << said_;
  EXPECT_FALSE(fs::exists(state_file_path(path("whole"), 0)));  // the result holds them now
  interrupted_run("resumed", {3});
  ASSERT_EQ(command({"run", "--resume", path("resumed"), "-q"}), 0) << said_;
  EXPECT_NE(said_.find("2 of 5 realizations kept from the checkpoint"), std::string::npos) << said_;
  EXPECT_FALSE(fs::exists(state_file_path(path("resumed"), 0)));
  const auto differences = testing::result_differences(path("whole"), path("resumed"));
  EXPECT_TRUE(differences.empty()) << differences.front();
}

// The state file lost, cut short (a disk that lost its last blocks) or with a
// number overwritten in the data of any of its states: realization 0 runs
// again, the run says so, and the result is the same. (Found: a file with
// overwritten data was resumed, its numbers in result.h5.)
TEST_F(CheckpointsWithStatesApart, RealizationZeroWithoutItsStatesRunsAgain) {
  ASSERT_EQ(command({"run", path("scene.toml"), "--out", path("whole"), "-q"}), 0) << said_;
  // The file holds three states of 300 bodies (x, v, m: 7200 bytes each), then its index.
  const std::vector<std::pair<std::string, std::uint64_t>> damages = {
      {"lost", 0},
      {"cut", 0},
      {"x of snapshot 0", 800},
      {"v of snapshot 1", 7200 + 2400 + 8},
      {"m of the final state", 2 * 7200 + 4800 + 2392}};
  for (const auto& [damage, offset] : damages) {
    SCOPED_TRACE(damage);
    const std::string out = "run-" + std::to_string(&damage - &damages[0].first);
    interrupted_run(out, {3});
    const fs::path file = state_file_path(path(out), 0);
    if (damage == "lost")
      fs::remove(file);
    else if (damage == "cut")
      fs::resize_file(file, fs::file_size(file) - 8);
    else
      testing::overwrite_eight_bytes(file, offset);
    ASSERT_EQ(command({"run", "--resume", path(out), "-q"}), 0) << said_;
    EXPECT_NE(said_.find("1 of 5 realizations kept from the checkpoint"), std::string::npos) << said_;
    EXPECT_NE(said_.find("realization 0 of ensemble 0 runs again"), std::string::npos) << said_;
    if (damage != "lost" && damage != "cut") {
      EXPECT_NE(said_.find(damage), std::string::npos) << said_;
    }
    const auto differences = testing::result_differences(path("whole"), path(out));
    EXPECT_TRUE(differences.empty()) << differences.front();
  }
}

// A run killed while realization 0 ran leaves its state file behind (no
// checkpoint refers to it): the next run into the directory is not refused for
// it, and removes it.
TEST_F(CheckpointsWithStatesApart, StateFilesThatAKilledRunLeftAreCleared) {
  fs::create_directories(path("run"));
  std::ofstream(state_file_path(path("run"), 0).string() + ".tmp") << "half a state";
  std::ofstream(state_file_path(path("run"), 1)) << "a state of a killed sweep";
  ASSERT_EQ(command({"run", path("scene.toml"), "--out", path("run"), "-q"}), 0) << said_;
  EXPECT_TRUE(fs::exists(path("run/result.h5")));
  for (const auto& entry : fs::directory_iterator(path("run")))
    EXPECT_FALSE(is_state_file(entry.path().filename())) << entry.path();
}

}  // namespace
}  // namespace shockgas::app
