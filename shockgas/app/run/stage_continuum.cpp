// Stage 2: the continuum solvers, side by side, each measured against the exact
// solver when the scene runs it too (its L1 distance, per unit length and
// relative: shockgas/compare/field_distance.hpp) and against its own initial mass (the drift).
#include <chrono>

#include "shockgas/app/output/run_results.hpp"
#include "shockgas/app/run/progress_bar.hpp"
#include "shockgas/app/run/run_internal.hpp"
#include "shockgas/continuum/registry.hpp"
#include "shockgas/continuum/solve.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::app {

namespace {

double total(const std::vector<double>& rho, double length) {
  double sum = 0;
  for (double x : rho) sum += x;
  return sum * length / static_cast<double>(rho.size());
}

void assess(ContinuumRun& run, const continuum::ContinuumResult* exact, double mass0) {
  const auto& r = run.result;
  if (!r.rho.empty()) run.mass_drift = total(r.rho, r.length) / mass0 - 1;  // 0 up to rounding if conserved
  if (!exact || exact == &r || exact->v.size() != r.v.size()) return;
  run.l1_v = compare::l1_distance(r.v, exact->v, compare::L1Scale::about_mean);
  if (!r.rho.empty() && r.rho.size() == exact->rho.size()) {
    run.l1_rho = compare::l1_distance(r.rho, exact->rho, compare::L1Scale::absolute);
    run.w1_rho = compare::mass_distance(r.rho, exact->rho);
  }
}

}  // namespace

ProgressCallback wall_limited(const Scene& scene, const std::string& name, ProgressCallback report) {
  const double limit = scene.has_particles ? scene.particles.max_wall_seconds : 0;
  if (limit <= 0) return report;
  const auto start = std::chrono::steady_clock::now();
  return [=](double fraction, double t, std::uint64_t events) {
    if (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() > limit)
      throw RunError("continuum: " + name + " had reached t = " + to_text(t, 4) + " of " +
                     to_text(scene.continuum_t_end()) + " when the wall limit particles.max_wall_seconds = " +
                     to_text(limit) + " s ran out (a smaller continuum.t_end or fewer cells end sooner)");
    if (report) report(fraction, t, events);
  };
}

std::vector<ContinuumRun> run_continuum(const Scene& scene, const InitialCondition& initial,
                                        ProgressBar& progress) {
  const InitialField& field = initial.field();
  std::vector<ContinuumRun> runs;
  for (const auto& name : scene.continuum.solvers) {
    progress.stage("continuum/" + name);
    ContinuumRun run;
    run.result = continuum::solve(name, field, scene.continuum, scene.continuum_t_end(),
                                  wall_limited(scene, name, progress.callback()));
    runs.push_back(std::move(run));
    progress.finish();
  }
  const continuum::ContinuumResult* exact = nullptr;
  for (const auto& run : runs)
    if (continuum::solver_info(run.result.solver).exact) exact = &run.result;
  const double mass0 = total(continuum::cell_averages(field, scene.continuum.cells).rho, field.length);
  for (auto& run : runs) assess(run, exact, mass0);
  return runs;
}

}  // namespace shockgas::app
