// Stage 3: shocks are clusters. The particle state and the continuum field at
// the same time are compared (compare/snapshot_comparison.hpp).
#include "run_results.hpp"
#include "shockgas/continuum/solve.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::app {

namespace {

const continuum::ContinuumResult& compared_field(const Scene& scene,
                                                 const std::vector<ContinuumRun>& continuum) {
  for (const auto& run : continuum)
    if (run.result.solver == scene.compare.solver) return run.result;
  throw RunError("compare: solver " + scene.compare.solver + " did not run");
}

}  // namespace

// Both models at one time: if the particles stopped before t_end (a collapse, a
// limit), the compared solver is run again to the time they reached.
Comparison run_comparison(const Scene& scene, const InitialCondition& initial,
                          const ParticleResults& particles, const std::vector<ContinuumRun>& continuum) {
  const double t = particles.ensemble.first.stop.time;
  const continuum::ContinuumResult& field = compared_field(scene, continuum);
  Comparison c{scene.compare.solver, {}, ""};
  std::optional<continuum::ContinuumResult> rerun;
  if (t < field.t) {
    c.note = "particles stopped early; continuum re-run to their final time";
    rerun = continuum::solve(field.solver, initial.field(), scene.continuum, t);
  }
  const auto& compared = rerun ? *rerun : field;
  const double spacing = initial.length() / static_cast<double>(scene.initial.N);
  c.snapshot = compare::compare_snapshot(
      particles.ensemble.first.final_state, scene.initial.N, compared,
      compare::snapshot_params(scene.compare, scene.particles.r, scene.particles.delta, spacing, compared.t));
  return c;
}

}  // namespace shockgas::app
