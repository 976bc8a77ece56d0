// Stage 0: the initial condition, as every model sees it.
#include <nlohmann/json.hpp>

#include "run_state.hpp"

namespace shockgas::app {

void run_initial_stage(RunState& state) {
  const auto& p = state.scene.initial;
  state.summary["initial"] = {{"N", p.N},
                              {"length", domain_length(p)},
                              {"positions", name_of(p.positions)},
                              {"velocities", name_of(p.velocities)},
                              {"seed", p.seed}};
  if (!state.scene.has_particles) return;
  state.initial_bodies = make_initial_bodies(p, 0);
  const Bodies& b = state.initial_bodies;
  state.h5.write("/initial/x", b.x, "length", "initial positions (realization 0)");
  state.h5.write("/initial/v", b.v, "length/time", "initial velocities (realization 0)");
  state.h5.write("/initial/m", b.m, "mass", "initial masses (realization 0)");
  state.summary["initial"]["temperature"] = temperature(b);
}

}  // namespace shockgas::app
