// The cost of a checkpoint (shockgas/app/records/checkpoint.hpp): write_checkpoint of a
// finished study's records, fsync and rename included, into a directory under
// the system's temporary directory. A run writes one at most every
// output.checkpoint_minutes (default 10), so its cost is this time over 600 s.
//
// Args {V, R, N, S, B}: V ensembles (a sweep's variants) of R realizations
// each; realization 0 of each carries a final state of N bodies (x, v, m), the
// others only their records: S samples of every series column and a histogram
// of B bins at 3 times. Fig. 4 at the paper's size: {3, 500, 10^5, 6, 80};
// Fig. 1: {4, 10, 10^6, 200, 0}.
//
//   checkpoint_bench [benchmark flags]   e.g. --benchmark_repetitions=5
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "shockgas/app/records/checkpoint.hpp"

namespace {

using shockgas::app::RealizationRecord;

RealizationRecord record(std::size_t ensemble, std::size_t index, std::size_t N, std::size_t samples,
                         std::size_t bins) {
  RealizationRecord r{ensemble, index, {}};
  r.run.series.for_each_column([&](const char*, std::vector<double>& c) { c.assign(samples, 0.5); });
  r.run.histogram.zmax = 4;
  r.run.histogram.bins = bins;
  r.run.histogram.t = {1e3, 1e4, 1e5};
  r.run.histogram.density.assign(3 * bins, 0.25);
  if (index == 0) {
    r.run.final_state.x.assign(N, 1.0);
    r.run.final_state.v.assign(N, 0.1);
    r.run.final_state.m.assign(N, 1.0);
  }
  return r;
}

void BM_WriteCheckpoint(benchmark::State& state) {
  const auto V = static_cast<std::size_t>(state.range(0)), R = static_cast<std::size_t>(state.range(1)),
             N = static_cast<std::size_t>(state.range(2)), S = static_cast<std::size_t>(state.range(3)),
             B = static_cast<std::size_t>(state.range(4));
  shockgas::app::Checkpoint c;
  c.scene_text = "[initial]\nN = " + std::to_string(N) + "\n";
  for (std::size_t e = 0; e < V; ++e)
    for (std::size_t k = 0; k < R; ++k) c.records.push_back(record(e, k, N, S, B));
  const auto dir =
      std::filesystem::temp_directory_path() / ("shockgas-checkpoint-bench-" + std::to_string(getpid()));
  for (auto _ : state) shockgas::app::write_checkpoint(dir, c);
  state.counters["MB"] =
      static_cast<double>(std::filesystem::file_size(shockgas::app::checkpoint_path(dir))) / 1e6;
  std::filesystem::remove_all(dir);
}

BENCHMARK(BM_WriteCheckpoint)
    ->Args({3, 500, 100000, 6, 80})
    ->Args({4, 10, 1000000, 200, 0})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
