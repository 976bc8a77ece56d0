// The summary keys a teacher points at, declared once: the steepest local
// cooling exponent, the heaviest cluster of the particles and the heaviest shock
// of each solver (shockgas/compare/heaviest.hpp).
#include "shockgas/app/output/layout_declarations.hpp"
#include "shockgas/compare/heaviest.hpp"

namespace shockgas::app::layout {

namespace {

using Json = nlohmann::ordered_json;

Emit cluster(double HeaviestCluster::*field) {
  return [field](const RunResults& r, Emitter& out) {
    if (r.particles && r.particles->heaviest) out.json((*r.particles->heaviest).*field);
  };
}

Emit shock(double continuum::Shock::*field) {
  return [field](const RunResults& r, Emitter& out) {
    for (const auto& c : r.continuum)
      if (const auto s = compare::heaviest_shock(c.result)) out.json((*s).*field, {c.result.solver});
  };
}

}  // namespace

std::vector<Declaration> extreme_keys() {
  const Part a = Part::analysis, c = Part::continuum;
  const char* heavy = "solvers whose shocks hold mass";
  return {
      with_theory(
          key(a, "analysis.T_steepest_local_exponent", "1",
              "least d ln T / d ln t (the homogeneous-cooling plateau, when 1/eps << t << eps^(-3/2))",
              "with 2 or more samples",
              [](const RunResults& r, Emitter& out) {
                if (r.particles && r.particles->cooling.crossovers.t_min_exponent > 0)
                  out.json(r.particles->cooling.crossovers.min_exponent);
              }),
          compare::Law::crossovers, "-2 (homogeneous cooling, as eps -> 0)"),
      key(a, "analysis.heaviest_cluster_x", "length", "position of the heaviest cluster at the end", "",
          cluster(&HeaviestCluster::x)),
      key(a, "analysis.heaviest_cluster_m", "mass", "its mass", "", cluster(&HeaviestCluster::m)),
      key(a, "analysis.heaviest_cluster_v", "length/time", "its velocity (momentum / mass)", "",
          cluster(&HeaviestCluster::v)),
      key(c, "continuum.{solver}.heaviest_shock_x", "length", "position of the shock holding the most mass",
          heavy, shock(&continuum::Shock::x)),
      key(c, "continuum.{solver}.heaviest_shock_mass", "mass",
          "its mass (found shocks: the excess over the background)", heavy, shock(&continuum::Shock::mass)),
  };
}

}  // namespace shockgas::app::layout
