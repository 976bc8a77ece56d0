// Checkpoints (app/checkpoint.hpp): the file carries the finished
// realizations' records exactly; a resumed run that keeps them equals the
// uninterrupted run bit for bit; a damaged checkpoint, one of another build
// and a scene that is not the checkpoint's are refused with exit 2, the
// checkpoint left as it was and nothing written. A realization saved while it
// ran (run_state_file.hpp) continues from its state, to the uninterrupted
// run's result; a damaged state or one of another build is refused the same way. (Stopping a run by SIGKILL
// and SIGTERM in a child process: tests/checkpoint.cmake.)
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
#include "checkpoint.hpp"
#include "checkpointer.hpp"
#include "frames.hpp"
#include "realization_pool.hpp"
#include "run_state_file.hpp"
#include "shockgas/core/error.hpp"
#include "shockgas/particles/simulate.hpp"
#include "shockgas/version.hpp"
#include "state_file.hpp"

namespace shockgas::app {
namespace {

namespace fs = std::filesystem;

const char* kScene =
    "[initial]\nN = 300\n[particles]\nr = 0.5\nt_end = 15\nsamples = 7\nrealizations = 5\n"
    "histogram_bins = 10\nsnapshots = [4]\n[continuum]\nsolvers = [\"hopf_lax\"]\ncells = 200\n[compare]\n"
    "[output]\nplots = false\n";

std::string bytes_of(const fs::path& file) {
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

// A scene whose realizations pass safe points (sub-windows of the time windows):
// N >= 1024, bounces with a threshold.
const char* kLongerScene =
    "[initial]\nN = 20000\n[particles]\nr = 0.9\ndelta = 1e-2\nt_end = 40\nsamples = 9\nrealizations = 2\n"
    "snapshots = [5]\nthreads = 1\n[continuum]\nsolvers = [\"hopf_lax\"]\ncells = 200\n[compare]\n"
    "[output]\nplots = false\n";

// Saves the state of a realization's run once, at its safe point number `at`,
// into the state file of dir, as a running realization of a run does.
class SaveOnce : public particles::RunSaves {
 public:
  SaveOnce(fs::path dir, RunStateHeader header, int at)
      : dir_(std::move(dir)), header_(std::move(header)), at_(at) {}
  bool due() override { return ++points_ == at_; }
  void save(double t, double fraction,
            const std::function<void(particles::RunStateWriter&)>& write) override {
    header_.time = t, header_.fraction = fraction;
    write_run_state(dir_, header_, write);
  }

 private:
  fs::path dir_;
  RunStateHeader header_;
  int at_, points_ = 0;
};

class RunningStates : public Checkpoints {
 protected:
  void SetUp() override {
    Checkpoints::SetUp();
    std::ofstream(path("longer.toml")) << kLongerScene;
  }
  // An interrupted run into `out` of longer.toml: realization 1 finished,
  // realization 0 saved at its third safe point (version: of the build that saved it).
  void interrupted_inside(const std::string& out, const std::string& version = kVersion) const {
    const Scene scene = load_scene(path("longer.toml"));
    const InitialCondition ic(scene.initial);
    std::vector<RealizationRecord> finished{
        {0, 1, particles::run_realization(ic, 1, particle_params(scene))}};
    write_checkpoint(path(out), make_checkpoint(scene, "", "", std::move(finished)));
    SaveOnce saves(path(out), {version, kGitCommit, resolved_scene_text(scene), 0, 0, 0, 0, ""}, 3);
    particles::run_realization(ic, 0, particle_params(scene), {}, {&saves, nullptr});
  }
  fs::path state(const std::string& out) const { return run_state_path(path(out), 0, 0); }
};

TEST_F(RunningStates, ARunningRealizationContinuesFromItsState) {
  ASSERT_EQ(command({"run", path("longer.toml"), "--out", path("whole"), "-q"}), 0) << said_;
  interrupted_inside("resumed");
  ASSERT_TRUE(fs::exists(state("resumed")));
  ASSERT_EQ(command({"run", "--resume", path("resumed"), "-q"}), 0) << said_;
  EXPECT_NE(said_.find("1 of 2 realizations kept from the checkpoint, 1 continues from a saved state"),
            std::string::npos)
      << said_;
  EXPECT_FALSE(fs::exists(state("resumed")));  // the result holds it all
  const auto differences = testing::result_differences(path("whole"), path("resumed"));
  EXPECT_TRUE(differences.empty()) << differences.front();
}

// A write of a state or of checkpoint.bin killed half-way leaves its temporary
// file: the resumed run ignores it, and the result replaces the directory,
// temporary files included.
TEST_F(RunningStates, ATemporaryFileOfAKilledWriteIsLeftBehind) {
  interrupted_inside("resumed");
  std::ofstream(state("resumed").string() + ".partial-99999", std::ios::binary) << "half a state";
  std::ofstream(checkpoint_path(path("resumed")).string() + ".partial-99998", std::ios::binary) << "half";
  ASSERT_EQ(command({"run", "--resume", path("resumed"), "-q"}), 0) << said_;
  for (const auto& entry : fs::directory_iterator(path("resumed")))
    EXPECT_FALSE(is_checkpoint_file(entry.path().filename())) << entry.path();
}

TEST_F(RunningStates, ADamagedOrCutStateIsRefusedAndKept) {
  interrupted_inside("run");
  const std::string bytes = bytes_of(state("run"));
  for (const std::string& damaged : {bytes.substr(0, bytes.size() / 2), bytes.substr(0, 6),
                                     std::string(bytes).replace(bytes.size() / 3, 1, "\x7f")}) {
    std::ofstream(state("run"), std::ios::binary) << damaged;
    EXPECT_EQ(command({"run", "--resume", path("run"), "-q"}), 2);
    EXPECT_NE(said_.find("this one is damaged"), std::string::npos) << said_;
    EXPECT_EQ(bytes_of(state("run")), damaged);
    EXPECT_TRUE(fs::exists(checkpoint_path(path("run"))));
    EXPECT_FALSE(fs::exists(path("run/result.h5")));
  }
}

// Every state is checked whole before any realization continues (finding: a
// damaged state of realization 1 was found only when realization 1 started;
// realization 0 had continued by then and moved its states file on, and the
// checkpoint could no longer be resumed at all).
TEST_F(RunningStates, EveryStateIsCheckedBeforeAnyRealizationContinues) {
  interrupted_inside("run");
  std::string bytes = bytes_of(state("run"));
  bytes[bytes.size() / 2] ^= 0x01;
  std::ofstream(state("run"), std::ios::binary) << bytes;
  const Scene scene = load_scene(path("longer.toml"));
  try {
    Checkpointer resumed(path("run"), scene, "", "", {}, /*resuming=*/true, /*states=*/true);
    ADD_FAILURE() << "a damaged state was taken up";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("its checksum does not match its contents"), std::string::npos)
        << e.what();
  }
  EXPECT_EQ(bytes_of(state("run")), bytes);
}

TEST_F(RunningStates, AStateOfAnotherBuildIsRefused) {
  interrupted_inside("run", "0.0.1-other");
  EXPECT_EQ(command({"run", "--resume", path("run"), "-q"}), 2);
  EXPECT_NE(said_.find("it was saved by 0.0.1-other"), std::string::npos) << said_;
  EXPECT_TRUE(fs::exists(state("run")));
}

// A rank other than 0 of an MPI job (Checkpointer job_rank) continues the
// realization dealt to it from the state in the shared directory, to the
// uninterrupted realization's record, and leaves checkpoint.bin and the state
// to rank 0 (it writes and removes neither); starting a new run it removes no
// state either (rank 0 cleared the directory before dealing).
TEST_F(RunningStates, ARankOfAJobContinuesFromTheStateAndLeavesTheFilesToRankZero) {
  interrupted_inside("run");
  const Scene scene = load_scene(path("longer.toml"));
  const std::string checkpoint_bytes = bytes_of(checkpoint_path(path("run")));
  const std::string state_bytes = bytes_of(state("run"));
  const auto plan = std::make_shared<const EnsemblePlan>(scene, std::nullopt, std::nullopt);
  for (const bool resuming : {true, false}) {
    Checkpointer rank(path("run"), scene, "", "", {}, resuming, true, true);
    RealizationPool pool(plan, {WorkItem{0, 0}}, 1, false, {}, &rank);
    while (!pool.finished()) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    ASSERT_FALSE(pool.failure()) << pool.failure()->message;
    std::vector<RealizationRecord> got = pool.take_finished();
    ASSERT_EQ(got.size(), 1u);
    RealizationRecord whole{
        0, 0, particles::run_realization(InitialCondition(scene.initial), 0, particle_params(scene))};
    got[0].run.wall_seconds = whole.run.wall_seconds = 0;
    EXPECT_EQ(encode(got[0]), encode(whole)) << "resuming: " << resuming;
    EXPECT_EQ(rank.resumed_states().find(", 1 continues from a saved state (realization 0 at t = ") == 0,
              resuming)
        << rank.resumed_states();
    EXPECT_EQ(bytes_of(checkpoint_path(path("run"))), checkpoint_bytes);
    EXPECT_EQ(bytes_of(state("run")), state_bytes);
  }
}

}  // namespace
}  // namespace shockgas::app
