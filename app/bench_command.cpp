#include "shockgas/app/bench.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::app {
std::string run_bench(const BenchOptions&) { throw RunError("bench: not available in this build"); }
}  // namespace shockgas::app
