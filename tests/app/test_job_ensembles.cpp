// Rank 0's side of a job, in one process: a fake job whose rank 1 is played by
// the test, message by message. Rank 0 gathers records into the ensemble one
// process computes, and names a failed or signalled rank with its realization;
// with checkpoints, it saves what it gathered when the job is interrupted and
// deals out only the realizations a resumed checkpoint lacks.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <deque>
#include <filesystem>
#include <mutex>

#include "process_temp_path.hpp"
#include "shockgas/app/ensemble/checkpointer.hpp"
#include "shockgas/app/ensemble/realization_pool.hpp"
#include "shockgas/app/input/scene_parser.hpp"
#include "shockgas/app/jobs/job_ensembles.hpp"
#include "shockgas/app/run/progress_bar.hpp"
#include "shockgas/core/error.hpp"
#include "shockgas/core/interrupt.hpp"
#include "shockgas/particles/simulate.hpp"

namespace shockgas::app {
namespace {

// Rank 0 of two; what it sends is kept, what rank 1 "sends" is queued by the test.
class FakeJob : public Job {
 public:
  int rank() const override { return 0; }
  int size() const override { return 2; }
  void send(int dest, int tag, std::string bytes) override {
    std::lock_guard lock(mutex_);
    sent.push_back({dest, tag});
    if (tag == kItems) items_sent = std::move(bytes);
  }
  std::optional<JobMessage> receive() override {
    std::lock_guard lock(mutex_);
    if (inbox_.empty()) return std::nullopt;
    JobMessage m = std::move(inbox_.front());
    inbox_.pop_front();
    return m;
  }
  void from_rank_1(int tag, std::string bytes) {
    std::lock_guard lock(mutex_);
    inbox_.push_back({1, tag, std::move(bytes)});
  }
  std::vector<std::pair<int, int>> sent;  // (destination, tag)
  std::string items_sent;                 // what kItems dealt rank 1

 protected:
  void end_all(int) override { FAIL() << "the job was ended"; }

 private:
  std::mutex mutex_;
  std::deque<JobMessage> inbox_;
};

std::string doubles(std::vector<double> d) {
  return std::string(reinterpret_cast<const char*>(d.data()), d.size() * sizeof(double));
}

Scene scene_of(std::size_t realizations) {
  return parse_scene("[initial]\nN = 200\n[particles]\nr = 0.5\nt_end = 10\nsamples = 6\nrealizations = " +
                         std::to_string(realizations) + "\n",
                     "test.toml");
}

std::shared_ptr<const EnsemblePlan> plan_of(std::size_t realizations) {
  return std::make_shared<const EnsemblePlan>(scene_of(realizations), std::nullopt, std::nullopt);
}

// Realization w of the plan, as the rank that ran it sends it.
RealizationRecord record_of(const EnsemblePlan& plan, const WorkItem& w) {
  RealizationRecord r{w.ensemble, w.index, {}};
  const InitialCondition& ic = plan.initial(w.ensemble);
  r.run = particles::simulate(ic.realization(w.index), ic.length(), plan.scene(w.ensemble).particles);
  if (w.index != 0) strip_states(r.run);
  return r;
}

// The records rank 0 returned are every realization once, in index order, and
// reduce to the ensemble one process computes, bit for bit.
void expect_the_ensemble_of_one_process(const EnsemblePlan& plan, const ComputedRecords& got) {
  const std::uint64_t n = plan.realizations(0);
  ASSERT_EQ(got.records.size(), n);
  for (std::uint64_t k = 0; k < n; ++k) EXPECT_EQ(got.records[k].index, k);
  const auto gathered = reduce_ensemble_records(got.records, n);
  const auto alone = particles::run_ensemble(plan.initial(0), plan.scene(0).particles);
  ASSERT_EQ(gathered.T.mean.size(), alone.T.mean.size());
  EXPECT_EQ(std::memcmp(gathered.T.mean.data(), alone.T.mean.data(), alone.T.mean.size() * sizeof(double)),
            0);
}

TEST(JobEnsembles, RankZeroGathersTheRecordsOfRankOne) {
  const auto plan = plan_of(4);
  FakeJob job;
  for (const WorkItem& w : plan->share(1, 2))  // realizations 1 and 3, as rank 1 would send them
    job.from_rank_1(kRecord, encode(record_of(*plan, w)));
  ProgressBar quiet(false);
  const ComputedRecords got = compute_records(&job, plan, 1, quiet);
  expect_the_ensemble_of_one_process(*plan, got);
  EXPECT_NE(std::find(job.sent.begin(), job.sent.end(), std::pair{1, int{kDone}}), job.sent.end());
  EXPECT_EQ(job.items_sent, doubles({0, 1, 0, 3}));  // rank 1 was dealt realizations 1 and 3
}

// What rank 0 says when the job fails: compute_records' error.
std::string failure_of(FakeJob& job, std::size_t realizations) {
  ProgressBar quiet(false);
  try {
    compute_records(&job, plan_of(realizations), 1, quiet);
  } catch (const RunError& e) {
    return e.what();
  }
  return "no error";
}

TEST(JobEnsembles, ARealizationThatFailsOnRankOneIsNamed) {
  FakeJob job;
  job.from_rank_1(kFailed, doubles({0, 0, 3}) + "out of memory");
  EXPECT_EQ(failure_of(job, 4),
            "rank 1 failed in realization 3: out of memory; the job stops, no result is written");
}

// The threads of this process, as the kernel lists them.
std::size_t threads_running() {
  std::size_t n = 0;
  for ([[maybe_unused]] const auto& task : std::filesystem::directory_iterator("/proc/self/task")) ++n;
  return n;
}

// Rank 1 fails while rank 0's own realization has seconds still to run: the
// job ends with the error and no thread of it goes on running (a thread left
// running outlives what the process destroys at its exit, and crashes it).
TEST(JobEnsembles, ARealizationStillRunningWhenTheJobFailsEndsWithIt) {
  const std::size_t before = threads_running();
  FakeJob job;
  job.from_rank_1(kFailed, doubles({0, 0, 1}) + "out of memory");
  const auto plan = std::make_shared<const EnsemblePlan>(
      parse_scene("[initial]\nN = 100000\n[particles]\nr = 0.5\nt_end = 100000\nrealizations = 2\n",
                  "long.toml"),
      std::nullopt, std::nullopt);
  ProgressBar quiet(false);
  EXPECT_THROW(compute_records(&job, plan, 1, quiet), RunError);
  EXPECT_EQ(threads_running(), before);
}

// Bad input on rank 1 (a damaged saved state) ends the job as bad input ends one
// process: an InputError, which the command maps to exit 2.
TEST(JobEnsembles, BadInputOnRankOneIsAnInputError) {
  FakeJob job;
  job.from_rank_1(kFailed, doubles({1, 0, 3}) + "--resume = \"s.bin\": damaged");
  ProgressBar quiet(false);
  try {
    compute_records(&job, plan_of(4), 1, quiet);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(),
                 "rank 1 failed in realization 3: --resume = \"s.bin\": damaged; the job stops, no result is "
                 "written");
  }
}

TEST(JobEnsembles, ARankStoppedByItsOwnSignalIsNamed) {
  FakeJob job;
  job.from_rank_1(kInterrupted, doubles({15, 0, 1}));  // SIGTERM, running realization 1
  EXPECT_EQ(
      failure_of(job, 4),
      "rank 1 was stopped by signal 15 while running realization 1; the job stops, no result is written");
}

class JobInterrupted : public ::testing::Test {
 protected:
  void SetUp() override { request_interrupt(InterruptMode::abort, 15); }
  void TearDown() override { clear_interrupt(); }
};

// The launcher ends the job with SIGTERM because rank 1 died: it cannot answer.
TEST_F(JobInterrupted, ARankThatCannotAnswerIsNamedWithItsRealization) {
  FakeJob job;
  job.from_rank_1(kProgress,
                  doubles({0.5, 3.0, 0, 0, 3}));  // fraction, time, collisions; running realization 3
  EXPECT_EQ(
      failure_of(job, 4),
      "rank 1 stopped while running realization 3 (killed, or its node was lost); the job stops, no result "
      "is written");
  EXPECT_NE(std::find(job.sent.begin(), job.sent.end(), std::pair{1, int{kStop}}), job.sent.end());
}

// Every rank got the signal (a pre-emption): an interruption, not a failure.
TEST_F(JobInterrupted, WhenEveryRankAnswersTheJobIsInterrupted) {
  FakeJob job;
  job.from_rank_1(kInterrupted, doubles({15, 0, 1}));
  ProgressBar quiet(false);
  EXPECT_THROW(compute_records(&job, plan_of(4), 1, quiet), Interrupted);
}

// Rank 0 of a job that keeps checkpoints, in a directory of this test's own.
class JobCheckpoints : public ::testing::Test {
 protected:
  void TearDown() override {
    clear_interrupt();
    std::filesystem::remove_all(dir_);
  }
  std::unique_ptr<Checkpointer> checkpointer(std::size_t realizations,
                                             std::vector<RealizationRecord> kept = {}) {
    return std::make_unique<Checkpointer>(dir_, scene_of(realizations), "", "", KeptWork{std::move(kept)});
  }
  std::vector<std::uint64_t> saved_indices() const {
    std::vector<std::uint64_t> indices;
    for (const auto& r : read_checkpoint(dir_).records) indices.push_back(r.index);
    std::sort(indices.begin(), indices.end());
    return indices;
  }
  const std::filesystem::path dir_ = testing_support::fresh_process_directory("shockgas-job-", "checkpoints");
};

// A pre-emption: SIGTERM to every rank. Rank 1's record arriving with its answer
// is saved with rank 0's own, what rank 1 said its state holds is in the one
// message, and the job is interrupted.
TEST_F(JobCheckpoints, AnInterruptedJobSavesWhatRankZeroGathered) {
  const auto plan = plan_of(4);
  FakeJob job;
  job.from_rank_1(kRecord, encode(record_of(*plan, {0, 1})));
  job.from_rank_1(kInterrupted, doubles({15, 0, 3}));  // then stopped in realization 3
  job.from_rank_1(kSaved, "; realization 3 saved at t = 2.5");
  auto checkpoints = checkpointer(4);
  request_interrupt(InterruptMode::checkpoint, 15);
  ProgressBar quiet(false);
  try {
    compute_records(&job, plan, 1, quiet, checkpoints.get());
    FAIL() << "the job was not interrupted";
  } catch (const CheckpointTaken& c) {
    EXPECT_NE(c.note().find("; realization 3 saved at t = 2.5"), std::string::npos) << c.note();
  }
  const auto saved =
      saved_indices();  // rank 0's own 0 and 2 too if they finished before the request was seen
  EXPECT_TRUE(std::count(saved.begin(), saved.end(), 1u)) << "rank 1's record not saved";
  EXPECT_FALSE(std::count(saved.begin(), saved.end(), 3u)) << "the realization stopped was saved";
  EXPECT_NE(std::find(job.sent.begin(), job.sent.end(), std::pair{1, int{kStop}}), job.sent.end());
}

// Rank 1 was killed, and the launcher ends the others: what was gathered is
// saved, then the rank that did not answer is named.
TEST_F(JobCheckpoints, ALostRankIsNamedAfterTheCheckpointIsSaved) {
  const auto plan = plan_of(4);
  FakeJob job;
  job.from_rank_1(kRecord, encode(record_of(*plan, {0, 1})));
  job.from_rank_1(kProgress, doubles({0.5, 3.0, 0, 0, 3}));  // running realization 3, then silent
  auto checkpoints = checkpointer(4);
  request_interrupt(InterruptMode::checkpoint, 15);
  ProgressBar quiet(false);
  try {
    compute_records(&job, plan, 1, quiet, checkpoints.get());
    FAIL() << "the job did not fail";
  } catch (const RunError& e) {
    const std::string said = e.what();
    EXPECT_EQ(said.substr(0, said.find(';')),
              "rank 1 stopped while running realization 3 (killed, or its node was lost)");
    EXPECT_NE(said.find("; checkpoint written: "), std::string::npos) << said;
  }
  const auto saved = saved_indices();
  EXPECT_TRUE(std::count(saved.begin(), saved.end(), 1u)) << "rank 1's record not saved";
}

// A resumed job deals out only the realizations its checkpoint lacks, and
// returns the kept records with the new ones: every realization once.
TEST_F(JobCheckpoints, AResumedJobRunsOnlyWhatTheCheckpointLacks) {
  const auto plan = plan_of(5);
  std::vector<RealizationRecord> kept;
  for (std::uint64_t k : {0, 1, 3}) kept.push_back(record_of(*plan, {0, k}));
  auto checkpoints = checkpointer(5, std::move(kept));
  FakeJob job;
  job.from_rank_1(kRecord, encode(record_of(*plan, {0, 4})));  // remaining 2, 4: rank 1 is dealt 4
  ProgressBar quiet(false);
  const ComputedRecords got = compute_records(&job, plan, 1, quiet, checkpoints.get());
  EXPECT_EQ(job.items_sent, doubles({0, 4}));
  expect_the_ensemble_of_one_process(*plan, got);
}

}  // namespace
}  // namespace shockgas::app
