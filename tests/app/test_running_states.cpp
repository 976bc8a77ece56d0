// Realizations saved while they ran (run_state_file.hpp): a resumed run
// continues each from its state, to the uninterrupted run's result; a damaged
// state, one cut short or one of another build is refused with exit 2 and
// kept, and every state is checked before any realization continues.
#include <gtest/gtest.h>

#include "app/checkpoint_fixture.hpp"
#include "shockgas/app/input/scene_parser.hpp"

namespace shockgas::app {
namespace {

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
