// Rank 0's side of a job, in one process: a fake job whose rank 1 is played by
// the test, message by message. Rank 0 gathers records into the ensemble one
// process computes, and names a failed or signalled rank with its realization.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <deque>
#include <mutex>

#include "job_ensembles.hpp"
#include "progress_bar.hpp"
#include "realization_pool.hpp"
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
  void send(int dest, int tag, std::string) override {
    std::lock_guard lock(mutex_);
    sent.push_back({dest, tag});
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

 protected:
  void end_all(int) override { FAIL() << "the job was ended"; }

 private:
  std::mutex mutex_;
  std::deque<JobMessage> inbox_;
};

std::string doubles(std::vector<double> d) {
  return std::string(reinterpret_cast<const char*>(d.data()), d.size() * sizeof(double));
}

std::shared_ptr<const EnsemblePlan> plan_of(std::size_t realizations) {
  const Scene s =
      parse_scene("[initial]\nN = 200\n[particles]\nr = 0.5\nt_end = 10\nsamples = 6\nrealizations = " +
                      std::to_string(realizations) + "\n",
                  "test.toml");
  return std::make_shared<const EnsemblePlan>(s, std::nullopt, std::nullopt);
}

TEST(JobEnsembles, RankZeroGathersTheRecordsOfRankOne) {
  const auto plan = plan_of(4);
  FakeJob job;
  for (const WorkItem& w : plan->share(1, 2)) {  // realizations 1 and 3, as rank 1 would send them
    RealizationRecord r{w.ensemble, w.index, {}};
    const InitialCondition& ic = plan->initial(0);
    r.run = particles::simulate(ic.realization(w.index), ic.length(), plan->scene(0).particles);
    strip_states(r.run);
    job.from_rank_1(kRecord, encode(r));
  }
  ProgressBar quiet(false);
  const ComputedRecords got = compute_records(&job, plan, 1, quiet);
  ASSERT_EQ(got.records.size(), 4u);
  for (std::uint64_t k = 0; k < 4; ++k) EXPECT_EQ(got.records[k].index, k);
  const auto gathered = reduce_ensemble_records(got.records, 4);
  const auto alone = particles::run_ensemble(plan->initial(0), plan->scene(0).particles);
  ASSERT_EQ(gathered.T.mean.size(), alone.T.mean.size());
  EXPECT_EQ(std::memcmp(gathered.T.mean.data(), alone.T.mean.data(), alone.T.mean.size() * sizeof(double)),
            0);
  EXPECT_NE(std::find(job.sent.begin(), job.sent.end(), std::pair{1, int{kDone}}), job.sent.end());
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
  job.from_rank_1(kFailed, doubles({0, 3}) + "out of memory");
  EXPECT_EQ(failure_of(job, 4),
            "rank 1 failed in realization 3: out of memory; the job stops, no result is written");
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
  job.from_rank_1(kProgress, doubles({0.5, 3.0, 0, 3}));  // running realization 3
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

}  // namespace
}  // namespace shockgas::app
