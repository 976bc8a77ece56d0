// Realization 0's state file (shockgas/app/records/state_file.hpp): a state read back checks
// its columns against their checksums, whichever way it is read; the whole
// file is checked before a resume (tests/app/test_checkpoint.cpp: a resumed
// run then runs realization 0 again).
#include <gtest/gtest.h>

#include <functional>
#include <optional>
#include <string>

#include "app/run_dir_checks.hpp"
#include "shockgas/app/records/state_file.hpp"
#include "shockgas/core/bodies.hpp"
#include "shockgas/core/error.hpp"
#include "shockgas/particles/state_sink.hpp"

namespace shockgas::app {
namespace {

namespace fs = std::filesystem;

// A state read back checks its columns: overwritten data ends the read with a
// RunError naming the file and the state, whichever way it is read.
TEST(StateFile, ADamagedColumnIsRefusedWhenRead) {
  const fs::path dir = testing::fresh_dir("state-file-damaged");
  const fs::path file = state_file_path(dir, 0);
  Bodies bodies;
  for (int k = 0; k < 5000; ++k) bodies.x.push_back(k), bodies.v.push_back(0.5 * k), bodies.m.push_back(1.0);
  {
    StateFileWriter writer(file);
    writer.sink().final_state(2.0, particles::BodiesReader(bodies));
    writer.commit();
  }
  const auto whole = StoredStates::open(file);
  double sum = 0;
  whole->final_state()->read([&](const double*, const double* v, const double*, std::size_t n) {
    for (std::size_t k = 0; k < n; ++k) sum += v[k];
  });
  EXPECT_EQ(sum, 0.5 * 4999 * 5000 / 2);
  EXPECT_FALSE(StoredStates::problem(file).has_value());
  testing::overwrite_eight_bytes(file, 5000 * 8 + 4100 * 8);  // v of body 4100, in the read's second chunk
  const auto damaged = StoredStates::open(file);
  const auto refused = [&](const std::function<void()>& read) {
    try {
      read();
    } catch (const RunError& e) {
      return std::string(e.what()).find(file.string() + " is damaged: v of the final state") !=
             std::string::npos;
    }
    return false;
  };
  EXPECT_TRUE(refused([&] {
    damaged->final_state()->read([](const double*, const double*, const double*, std::size_t) {});
  }));
  EXPECT_TRUE(refused([&] { damaged->final_state()->read_column(1, [](const double*, std::size_t) {}); }));
  EXPECT_FALSE(refused([&] { damaged->final_state()->read_column(0, [](const double*, std::size_t) {}); }));
  ASSERT_TRUE(StoredStates::problem(file).has_value());
  EXPECT_NE(StoredStates::problem(file)->find("v of the final state"), std::string::npos);
}

// The final state reaches the file only where FinalStateUse::keep says so; its
// heaviest cluster, from FinalStateUse::heaviest, either way (the command's
// summary reads it without the state), checked as every state is.
TEST(StateFile, AFinalStateNotKeptLeavesItsHeaviestCluster) {
  const fs::path dir = testing::fresh_dir("state-file-heaviest");
  Bodies bodies;
  for (int k = 0; k < 5000; ++k) bodies.x.push_back(k), bodies.v.push_back(0.5 * k), bodies.m.push_back(1.0);
  std::size_t offered = 0;
  const auto write = [&](const fs::path& file, bool keep) {
    FinalStateUse use{[&](std::size_t n) { return offered = n, keep; },
                      [](double t, const particles::StateReader& state) {
                        return std::optional<HeaviestCluster>({t, -1.5, static_cast<double>(state.size())});
                      }};
    StateFileWriter writer(file, std::move(use));
    writer.sink().final_state(2.0, particles::BodiesReader(bodies));
    writer.commit();
  };
  const fs::path apart = state_file_path(dir, 0), kept = state_file_path(dir, 1);
  write(apart, false);
  EXPECT_EQ(offered, 5000U);
  write(kept, true);
  for (const fs::path& file : {apart, kept}) {
    const auto states = StoredStates::open(file);
    const std::optional<HeaviestCluster> h = states->heaviest_cluster();
    ASSERT_TRUE(h.has_value());
    EXPECT_EQ(h->x, 2.0);
    EXPECT_EQ(h->v, -1.5);
    EXPECT_EQ(h->m, 5000.0);
    EXPECT_FALSE(StoredStates::problem(file).has_value());
  }
  EXPECT_EQ(StoredStates::open(apart)->final_state(), nullptr);
  ASSERT_NE(StoredStates::open(kept)->final_state(), nullptr);
  EXPECT_EQ(StoredStates::open(kept)->final_state()->size(), 5000U);
  EXPECT_LT(fs::file_size(apart), 1000U);    // 3 numbers and the index, not the 120 kB state
  testing::overwrite_eight_bytes(apart, 8);  // v of the heaviest cluster
  ASSERT_TRUE(StoredStates::problem(apart).has_value());
  EXPECT_NE(StoredStates::problem(apart)->find("v of the heaviest cluster"), std::string::npos);
}

}  // namespace
}  // namespace shockgas::app
