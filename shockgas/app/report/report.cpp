// report.md of a single run, part by part.
#include "shockgas/app/report/report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <sstream>

#include "shockgas/app/output/statistics_files.hpp"
#include "shockgas/app/output/theory_scopes.hpp"
#include "shockgas/compare/cooling_corrections.hpp"
#include "shockgas/compare/theory.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::app {

std::string brief(double value) { return to_text(value, 4); }

std::string percent(double fraction) {
  return std::isfinite(fraction) ? brief(100 * fraction) + " %" : "nan";
}

namespace {

void particles_part(std::ostream& out, const Scene& scene, const particles::EnsembleResult& e) {
  const auto& p = scene.particles;
  const auto& stop = e.first.stop;
  const double rate = e.wall_seconds > 0 ? static_cast<double>(e.total_collisions) / e.wall_seconds : 0.0;
  out << "## Particles\n\n";
  out << "- " << scene.initial.N << " particles, r = " << brief(p.r);
  if (particles::collision_rule(p).merges_only())
    out << " (every collision merges)";
  else
    out << ", delta = " << brief(p.delta) << " (" << name_of(p.subthreshold) << " below it)";
  if (p.restitution_law != particles::kConstantRestitution)
    out << ", restitution law `" << p.restitution_law << "`";
  out << ", " << p.realizations << " realization(s), solver `" << name_of(p.solver) << "`.\n";
  out << "- " << e.total_collisions << " collisions in " << brief(e.wall_seconds) << " s ("
      << brief(std::round(rate)) << " per second).\n";
  if (p.solver == particles::ParticleSolver::events) {
    const particles::RunSchedule& s = e.first.schedule;
    out << "- Event order: " << s.order << (s.why_global.empty() ? "" : " (" + s.why_global + ")") << ".\n";
  }
  out << "- Run ended: " << to_string(stop.reason) << " at t = " << brief(stop.time);
  if (stop.reason == particles::StopReason::collapse)
    out << " (inelastic collapse at x = " << brief(stop.position) << ")";
  if (stop.reason == particles::StopReason::stall)
    out << " (time stopped advancing at x = " << brief(stop.position)
        << " through rounding: results up to this time are kept)";
  out << ".\n\n";
}

// "+- e (jackknife over n realizations)", or the words that say there is none.
std::string error_text(const std::optional<compare::JackknifeEstimate>& e) {
  if (e && std::isfinite(e->error))
    return "+- " + brief(e->error) + " (jackknife over " + std::to_string(e->samples) + " realizations)";
  return "(no error estimate from one realization)";
}

// The fit's line; where the sticky-gas law holds, the departure from it in words; a
// crossover read off the curve inside the window.
void fit_lines(std::ostream& out, const RunResults& r, const compare::PowerLawFit& fit) {
  const auto& errors = r.particles->errors;
  const auto jackknife = errors ? std::optional(errors->T_exponent) : std::nullopt;
  out << "- T ~ t^a with a = " << brief(fit.exponent) << " " << error_text(jackknife) << " on ["
      << brief(fit.t_min) << ", " << brief(fit.t_max) << "]; " << law_note(r, compare::Law::sticky_cooling)
      << ".\n";
  if (law_scope(r, compare::Law::sticky_cooling).holds) {
    const auto corrections = compare::cooling_corrections(
        r.scene->initial.N, r.scene->initial.positions == Positions::lattice, fit.t_min, fit.t_max);
    out << "- "
        << compare::cooling_departure_text(fit.exponent, jackknife ? jackknife->error : std::nan(""),
                                           jackknife ? jackknife->samples : 1, corrections, fit.t_min,
                                           fit.t_max, r.particles->same_starts)
        << "\n";
  }
  // The window follows the theory's crossovers; one read off the curve may fall inside it.
  const auto& c = r.particles->cooling.crossovers;
  for (const auto& [name, t] : {std::pair{"t_dissip", c.t_dissip}, std::pair{"t_stick", c.t_stick}})
    if (t > fit.t_min && t < fit.t_max)
      out << "- The measured " << name << " = " << brief(t)
          << " lies inside the fit window: the fit may span the "
          << "crossover the curve shows there, and its exponent mix two regimes.\n";
}

void cooling_part(std::ostream& out, const RunResults& r) {
  const compare::CoolingAnalysis& a = r.particles->cooling;
  if (a.local_exponent.empty()) {  // too few samples: not even the crossovers
    if (!a.not_determined.empty()) out << "- cooling_law: not determined (" << a.not_determined << ").\n\n";
    return;
  }
  const auto& c = a.crossovers;
  out << "## Cooling law\n\n";
  if (a.fit)
    fit_lines(out, r, *a.fit);
  else
    out << "- T ~ t^a: not fitted (" << a.not_determined << ").\n";
  const bool crossed = std::isfinite(c.t_dissip) && std::isfinite(c.t_stick);
  out << "- Crossovers read off d ln T / d ln t: t_dissip = " << brief(c.t_dissip)
      << ", t_stick = " << brief(c.t_stick) << (crossed ? "" : " (nan: not crossed in the sampled window)")
      << "; ";
  if (law_scope(r, compare::Law::crossovers).holds)
    out << law_note(r, compare::Law::crossovers) << " = " << brief(c.t_dissip_theory) << ", "
        << brief(c.t_stick_theory) << ".\n\n";
  else
    out << law_note(r, compare::Law::crossovers) << ".\n\n";
}

void distribution_part(std::ostream& out, const RunResults& r) {
  const compare::DistributionAnalysis& a = r.particles->distribution;
  const std::string theory = law_note(r, compare::Law::velocity_scaling);
  if (a.collapse_distance)
    out << "## Velocity distribution\n\n- Collapse of P(v,t) t^(-1/3) against z = (v - <v>) t^(1/3) over "
        << a.late.size() << " times in [" << brief(a.late.front().t) << ", " << brief(a.late.back().t)
        << "]: mean L1 distance " << brief(*a.collapse_distance) << " "
        << error_text(r.particles->errors ? std::optional(r.particles->errors->distribution.collapse_distance)
                                          : std::nullopt)
        << " (0 = perfect collapse, 2 = disjoint; a finite sample's histograms differ by their noise); "
        << theory << ".\n";
  if (!a.not_determined.empty()) {
    out << "- velocity_distribution: not determined (" << a.not_determined << ").\n\n";
    return;
  }
  if (!a.collapse_distance) return;
  out << "- Tail ln Phi ~ -c |z|^a for |z| >= " << brief(a.tail_z_min);
  if (a.tail.at_bound)
    out << ": not determined (the best a sits at the scan bound: too few or too noisy tail points).\n\n";
  else
    out << " (one standard deviation): a = " << brief(a.tail.exponent) << " "
        << error_text(r.particles->errors ? std::optional(r.particles->errors->distribution.tail_exponent)
                                          : std::nullopt)
        << ".\n\n";
}

// particle_start: the continuum started from the particles (not from v0(x),
// rho0(x)), where the exact solution is that of the point masses.
void continuum_part(std::ostream& out, const Scene& scene, const std::vector<ContinuumRun>& runs,
                    bool particle_start) {
  out << "## Continuum at t = " << brief(scene.continuum_t_end()) << "\n\n";
  for (const auto& run : runs) {
    const auto& r = run.result;
    out << "- `" << r.solver << "`: " << r.x.size() << " cells, " << brief(r.wall_seconds) << " s";
    if (run.l1_v) {
      out << "; L1 distance to the exact solution per unit length: v " << brief(run.l1_v->per_length) << " ("
          << percent(run.l1_v->relative) << " of the exact v's variation about its mean)";
      if (run.w1_rho)
        out << "; where the mass is: it must move on average " << percent(*run.w1_rho)
            << " of the domain to match the exact density (Wasserstein-1 of the cumulative masses; one cell "
               "is "
            << percent(1.0 / static_cast<double>(r.x.size())) << ")";
    }
    if (!r.method_note.empty()) out << " (" << r.method_note << ")";
    out << "\n";
  }
  const bool distances = std::any_of(runs.begin(), runs.end(), [](const ContinuumRun& c) { return c.l1_v; });
  if (particle_start && distances)
    out << "\nThe exact solution here is that of the particles' own start, the point masses; the grids "
           "start from their velocities and masses in cells (interpolated between particles where the "
           "cells outnumber them), another datum. The distances above include that difference, whatever "
           "the cells: they measure a grid's own error only where it is the larger; the schemes' orders "
           "are measured on smooth data (docs/validate.md, grid convergence).\n";
  out << "\n";
}

// A cell of the comparison's table: the ideal where the law holds, else why there is none.
std::string ideal(const RunResults& r, compare::Law law, const std::string& value) {
  if (!law_scope(r, law).holds) return law_note(r, law);
  const compare::TheoryDeclaration& d = compare::declaration(law);
  return value + " (theory `" + d.id + "`, " + d.source + ")";
}

// For a gas of r > 0 the correspondence is approached as t / t_stick grows:
// how far into the sticky regime the comparison stands, so that a figure far
// from its ideal is read with it (the cooling gallery's r = 0.97 at 37
// t_stick: matched mass 0.76, its particles' slope near 0; the default
// scene's r = 0.5 at 1250 t_stick: 1 and 1.01).
void asymptotic_note(std::ostream& out, const RunResults& r, double t) {
  const double rest = r.scene->particles.r;
  if (!r.particles || !(rest > 0) || !law_scope(r, compare::Law::clusters_are_shocks).holds) return;
  const double t_stick = compare::sticking_time(rest);
  out << "- The ideals are those of the sticky gas, which a gas of r = " << brief(rest)
      << " approaches as t / t_stick grows: this comparison is at t = " << brief(t / t_stick)
      << " t_stick (t_stick ~ eps^(-3/2) = " << brief(t_stick)
      << "); a figure far from its ideal measures how far the gas is from them.\n\n";
}

void comparison_part(std::ostream& out, const RunResults& r) {
  using compare::Law;
  const Comparison& cmp = *r.comparison;
  const auto& c = cmp.snapshot;
  if (!cmp.note.empty())
    out << "- The particles stopped at t = " << brief(c.t) << " < t_end: `" << cmp.solver
        << "` is compared at that time.\n\n";
  out << "## Shocks and clusters at t = " << brief(c.t) << " (solver `" << cmp.solver << "`)\n\n";
  out << "| figure of merit | value | ideal |\n|---|---|---|\n";
  const double expected = compare::expected_shock_count(static_cast<double>(r.scene->initial.N), c.t);
  out << "| shocks (mass >= " << brief(c.min_mass) << ") | " << c.n_shocks << " | "
      << ideal(r, Law::shock_count,
               "N t^(-2/3) = " + brief(std::round(expected)) + " up to a factor of order 1, ratio " +
                   brief(c.shock_count_ratio));
  // The white-noise law is the continuum's: stated where the count's law holds
  // (from 10 t_stick), not at early times (t = 2: 472 against 1056 shocks found).
  if (cmp.n_shocks_exact && law_scope(r, Law::shock_count).holds)
    out << "; exact for this white noise: " << brief(*cmp.n_shocks_exact);
  out << " |\n";
  out << "| clusters (mass >= " << brief(c.min_mass) << ") | " << c.n_clusters << " | "
      << ideal(r, Law::clusters_are_shocks, "= shocks") << " |\n";
  out << "| matched cluster mass fraction | " << brief(c.match.matched_mass_fraction) << " | "
      << ideal(r, Law::clusters_are_shocks, "1") << " |\n";
  out << "| largest matched position error | " << brief(c.match.max_position_error) << " | "
      << ideal(r, Law::clusters_are_shocks, "0") << " |\n";
  const std::string slope = ideal(r, Law::ramp_slope, brief(compare::kSawtoothSlopeTimesT));
  out << "| median sawtooth slope x t (continuum) | " << brief(c.sawtooth.slope_times_t.median) << " | "
      << slope << " |\n";
  out << "| median sawtooth slope x t (particles) | " << brief(c.particle_sawtooth.slope_times_t.median)
      << " | " << slope << " |\n\n";
  asymptotic_note(out, r, c.t);
}

// The numbers of statistics.md under the report's own heading; or why there are none.
void statistics_part(std::ostream& out, const RunResults& r) {
  out << "## Shock statistics over the realizations (statistics.md)\n";
  if (!r.statistics) {
    out << "\nNone: no realization reached particles.t_end = " << brief(r.scene->particles.t_end)
        << ", and the statistics are of the clusters there; no statistics files were written.\n\n";
    return;
  }
  const std::string page = statistics_markdown(r.statistics->stats, r.statistics->about);
  out << page.substr(page.find('\n') + 1) << "\n";
}

}  // namespace

std::string phase_times_text(const std::vector<std::pair<std::string, double>>& phases) {
  std::ostringstream out;
  out << "## Time of each phase\n\n"
      << "Wall-clock time of each phase of this run, named as its progress lines name them.\n\n"
      << "| phase | wall time |\n|---|---|\n";
  char seconds[32];
  for (const auto& [name, time] : phases) {
    std::snprintf(seconds, sizeof seconds, "%.2f s", time);
    out << "| " << name << " | " << seconds << " |\n";
  }
  return out.str() + "\n";
}

std::string report_text(const RunResults& r) {
  const Scene& scene = *r.scene;
  std::ostringstream out;
  out << report_header(scene);
  if (r.particles) {
    particles_part(out, scene, r.particles->ensemble);
    cooling_part(out, r);
    distribution_part(out, r);
  }
  if (!r.continuum.empty())
    continuum_part(out, scene, r.continuum, r.initial && r.initial->field().from_bodies());
  if (r.comparison) comparison_part(out, r);
  if (r.scene->has_statistics && r.particles) statistics_part(out, r);
  return out.str();
}

}  // namespace shockgas::app
