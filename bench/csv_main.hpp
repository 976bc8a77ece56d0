#pragma once
// The main() of a Google Benchmark program that also writes a CSV table:
// takes --csv=FILE out of the arguments (and any flag `extra` accepts), runs
// the registered benchmarks, then calls write(FILE).
//
//   int main(int argc, char** argv) { return shockgas::bench::run_with_csv(argc, argv, "x.csv", write_csv); }
#include <benchmark/benchmark.h>

#include <cstring>
#include <functional>
#include <string>

namespace shockgas::bench {

inline int run_with_csv(int argc, char** argv, std::string csv,
                        const std::function<void(const std::string&)>& write,
                        const std::function<bool(const char*)>& extra = {}) {
  int kept = 1;
  for (int i = 1; i < argc; ++i) {
    if (std::strncmp(argv[i], "--csv=", 6) == 0)
      csv = argv[i] + 6;
    else if (!(extra && extra(argv[i])))
      argv[kept++] = argv[i];
  }
  argc = kept;
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  write(csv);
  return 0;
}

}  // namespace shockgas::bench
