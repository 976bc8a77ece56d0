// The sticky gas (r = 0) of 1000 bodies run by the event engine, and the exact
// sticky gas of the same bodies (the convex hull of the initial mass-momentum
// curve: E, Rykov & Sinai 1996): the same clusters, to rounding.
//   exit 0: they agree; 1: they differ; 2: the library refused the input.
#include <cmath>
#include <cstdio>
#include <cstring>

#include "shockgas/shockgas.hpp"

int main() {
  namespace sg = shockgas;
  if (std::strcmp(sg::library_version(), sg::kVersion) != 0) {
    std::printf("compiled against shockgas %s, running with %s\n", sg::kVersion, sg::library_version());
    return 1;
  }
  sg::InitialParams initial;
  initial.N = 1000;
  initial.seed = 7;
  const sg::Bodies bodies = sg::make_initial_bodies(initial);
  const double t = 50.0;

  sg::particles::ParticleParams params;
  params.r = 0.0;  // every collision merges
  params.geometry = sg::particles::Geometry::line;
  params.t_end = t;
  params.samples = 1;
  try {
    const sg::Bodies engine = sg::particles::simulate(bodies, 0.0, params).final_state;
    const sg::Bodies exact = sg::to_bodies(sg::sticky_clusters_line(bodies, t));
    // Positions after many merges agree to rounding: 1e-9 is far above it and far
    // below a wrong merge, which moves a cluster by O(1).
    bool same = engine.size() == exact.size();
    for (std::size_t i = 0; same && i < exact.size(); ++i)
      same = engine.m[i] == exact.m[i] && std::abs(engine.x[i] - exact.x[i]) < 1e-9 &&
             std::abs(engine.v[i] - exact.v[i]) < 1e-9;
    std::printf("shockgas %s: %zu bodies at t = %g: engine %zu clusters, exact hull %zu: %s\n",
                sg::library_version(), bodies.size(), t, engine.size(), exact.size(),
                same ? "agree" : "DIFFER");
    return same ? 0 : 1;
  } catch (const sg::InputError& e) {
    std::printf("refused: %s\n", e.what());
    return 2;
  }
}
