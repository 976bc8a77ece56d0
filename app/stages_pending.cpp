#include "run_state.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::app {
void run_compare_stage(RunState&) { throw RunError("compare: not built yet"); }
}  // namespace shockgas::app
