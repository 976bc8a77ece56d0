#include "run_state.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::app {
void run_particles_stage(RunState&) { throw RunError("particles: not built yet"); }
void run_continuum_stage(RunState&) { throw RunError("continuum: not built yet"); }
void run_compare_stage(RunState&) { throw RunError("compare: not built yet"); }
}  // namespace shockgas::app
