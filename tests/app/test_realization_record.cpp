// The per-realization records every parallel path hands to the one reduction:
// they carry a run exactly, the reduction does not depend on the order they
// come in and equals particles::run_ensemble bit for bit, and the plan deals
// every realization out once.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <random>

#include "shockgas/app/ensemble/ensemble_plan.hpp"
#include "shockgas/app/input/scene_parser.hpp"
#include "shockgas/app/records/realization_record.hpp"
#include "shockgas/core/error.hpp"
#include "shockgas/particles/simulate.hpp"

namespace shockgas::app {
namespace {

bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

Scene small_scene(std::size_t realizations) {
  return parse_scene("[initial]\nN = 300\n[particles]\nr = 0.5\nt_end = 15\nsamples = 7\nrealizations = " +
                         std::to_string(realizations) +
                         "\nhistogram_bins = 10\nsnapshots = [4]\nspacetime = true\nspacetime_frames = 5\n",
                     "test.toml");
}

particles::RunResult run_of(const Scene& s, std::uint64_t k) {
  const InitialCondition ic(s.initial);
  return particles::simulate(ic.realization(k), ic.length(), s.particles);
}

TEST(RealizationRecord, CarriesARunExactly) {
  const particles::RunResult run = run_of(small_scene(1), 0);
  ASSERT_FALSE(run.snapshots.empty());
  ASSERT_FALSE(run.spacetime.t.empty());
  ASSERT_TRUE(run.final_clusters.has_value());
  const RealizationRecord back = decode(encode({2, 0, run}));
  EXPECT_EQ(back.ensemble, 2u);
  EXPECT_EQ(back.index, 0u);
  const RecordFields a = to_fields(run), b = to_fields(back.run);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].first, b[i].first);
    EXPECT_TRUE(same_bits(a[i].second, b[i].second)) << a[i].first;
  }
  EXPECT_EQ(back.run.collisions, run.collisions);
  EXPECT_EQ(back.run.stop.reason, run.stop.reason);
  EXPECT_FALSE(back.states_apart);
  ASSERT_TRUE(back.run.final_clusters.has_value());
  EXPECT_TRUE(same_bits(back.run.final_clusters->m, run.final_clusters->m));
}

// Realization 0 whose states are in its state file says so through a message
// or a checkpoint; its run's fields are the same either way.
TEST(RealizationRecord, CarriesStatesApart) {
  particles::RunResult run = run_of(small_scene(1), 0);
  strip_states(run);
  const RealizationRecord back = decode(encode({0, 0, run, true}));
  EXPECT_TRUE(back.states_apart);
  EXPECT_EQ(to_fields(back.run).size(), to_fields(run).size());
}

TEST(RealizationRecord, CountsAboveTwoToThe53AreExact) {
  particles::RunResult run;
  run.collisions = (std::uint64_t{1} << 60) + 12345;  // not representable as a double
  EXPECT_EQ(from_fields(to_fields(run)).collisions, run.collisions);
}

TEST(RealizationRecord, MalformedInputIsARunError) {
  std::string bytes = encode({0, 3, run_of(small_scene(1), 0)});
  EXPECT_THROW(decode(bytes.substr(0, bytes.size() - 5)), RunError);
  RecordFields fields = to_fields(particles::RunResult{});
  fields.erase(fields.begin());  // series/t
  EXPECT_THROW(from_fields(fields), RunError);
}

// The reduction of records, in whatever order they arrive, is run_ensemble's.
TEST(RealizationRecord, ReducedInAnyOrderTheyEqualRunEnsemble) {
  const Scene s = small_scene(6);
  const particles::EnsembleResult whole = particles::run_ensemble(InitialCondition(s.initial), s.particles);
  std::vector<RealizationRecord> records;
  for (std::uint64_t k = 0; k < 6; ++k) {
    RealizationRecord r{0, k, run_of(s, k)};
    if (k > 0) strip_states(r.run);
    records.push_back(std::move(r));
  }
  std::shuffle(records.begin(), records.end(), std::mt19937(7));
  const particles::EnsembleResult gathered = reduce_ensemble_records(records, 6);
  EXPECT_TRUE(same_bits(gathered.t, whole.t));
  EXPECT_TRUE(same_bits(gathered.T.mean, whole.T.mean));
  EXPECT_TRUE(same_bits(gathered.T.stderr_, whole.T.stderr_));
  EXPECT_TRUE(same_bits(gathered.n_clusters.mean, whole.n_clusters.mean));
  EXPECT_TRUE(same_bits(gathered.dissipated.stderr_, whole.dissipated.stderr_));
  EXPECT_TRUE(same_bits(gathered.histogram, whole.histogram));
  EXPECT_TRUE(same_bits(gathered.first.final_state.x, whole.first.final_state.x));
  EXPECT_EQ(gathered.total_collisions, whole.total_collisions);
  records.pop_back();
  EXPECT_THROW(reduce_ensemble_records(records, 6), RunError);  // one missing
  records.push_back(records.front());
  EXPECT_THROW(reduce_ensemble_records(records, 6), RunError);  // one twice
}

TEST(EnsemblePlan, DealsEveryRealizationOfEveryVariantOnce) {
  const Scene sweep = parse_scene(
      "[initial]\nN = 100\n[particles]\nt_end = 5\nrealizations = 3\n"
      "[sweep]\nvariants = [\"particles.r=0.1\", \"particles.r=0.2; particles.realizations=5\"]\n",
      "sweep.toml");
  const EnsemblePlan plan(sweep, std::nullopt, std::nullopt);
  ASSERT_EQ(plan.items().size(), 8u);
  EXPECT_EQ(plan.items()[0], (WorkItem{0, 0}));  // realization-major: both variants' first come first
  EXPECT_EQ(plan.items()[1], (WorkItem{1, 0}));
  for (int ranks : {1, 2, 3, 9}) {
    std::vector<WorkItem> dealt;
    for (int r = 0; r < ranks; ++r)
      for (const WorkItem& w : plan.share(r, ranks)) dealt.push_back(w);
    ASSERT_EQ(dealt.size(), plan.items().size()) << ranks;
    for (const WorkItem& w : plan.items()) EXPECT_EQ(std::count(dealt.begin(), dealt.end(), w), 1) << ranks;
  }
  const EnsemblePlan slice(sweep, Slice{1, 4}, Slice{1, 2});
  EXPECT_EQ(slice.items(), (std::vector<WorkItem>{{1, 1}, {1, 2}, {1, 3}}));
  EXPECT_EQ(slice.describe({1, 2}), "realization 2 of variant 'particles.r=0.2; particles.realizations=5'");
}

TEST(EnsemblePlan, SlicesAreReadOrRefused) {
  EXPECT_EQ(parse_slice("3:7", "--realizations"), (Slice{3, 7}));
  for (const char* bad : {"7", "3:3", "5:2", "a:3", "-1:3", ":4", "1:"})
    EXPECT_THROW(parse_slice(bad, "--realizations"), InputError) << bad;
}

}  // namespace
}  // namespace shockgas::app
