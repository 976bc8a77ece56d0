// The keys of summary.json from the continuum, the comparison and a sweep,
// declared once: key, unit, meaning, and where each comes from.
#include <cmath>

#include "shockgas/app/output/layout_declarations.hpp"

namespace shockgas::app::layout {

namespace {

using Json = nlohmann::ordered_json;

std::vector<Declaration> continuum() {
  const Part p = Part::continuum;
  // f(run) -> optional Json, one value per solver.
  auto each = [](auto f) {
    return [f](const RunResults& r, Emitter& out) {
      for (const auto& c : r.continuum)
        if (auto value = f(c)) out.json(*value, {c.result.solver});
    };
  };
  using Run = ContinuumRun;
  using Opt = std::optional<Json>;
  auto optional = [](const std::optional<double>& x) { return x ? Opt(*x) : Opt(); };
  // One number of an L1 distance (field of run), null where it is not finite.
  using L1 = compare::L1Distance;
  const auto per_length = &L1::per_length, relative = &L1::relative;
  auto l1 = [](auto field, double L1::*number) {
    return [field, number](const Run& c) {
      const std::optional<L1>& d = field(c);
      if (!d) return Opt();
      const double x = (*d).*number;
      return Opt(std::isfinite(x) ? Json(x) : Json(nullptr));
    };
  };
  return {
      key(p, "continuum.{solver}.cells", "1", "grid cells", "",
          each([](const Run& c) { return Opt(c.result.x.size()); })),
      key(p, "continuum.{solver}.t", "time", "time of the fields", "",
          each([](const Run& c) { return Opt(c.result.t); })),
      key(p, "continuum.{solver}.wall_seconds", "s", "wall-clock time of the solve", "",
          each([](const Run& c) { return Opt(c.result.wall_seconds); })),
      key(p, "continuum.{solver}.method", "", "which path ran and why", "",
          each([](const Run& c) { return Opt(c.result.method_note); })),
      key(p, "continuum.{solver}.stats", "", "the solver's counters (steps, cells, rhs evaluations, ...)", "",
          each([](const Run& c) {
            if (c.result.stats.empty()) return Opt();
            Json stats;
            for (const auto& [k, v] : c.result.stats) stats[k] = v;
            return Opt(stats);
          })),
      key(p, "continuum.{solver}.n_shocks", "1", "shocks the solver knows", "solvers that know their shocks",
          each([](const Run& c) { return c.result.has_shocks ? Opt(c.result.shocks.size()) : Opt(); })),
      with_exact_value(
          key(p, "continuum.{solver}.mass_drift", "1",
              "sum rho dx at t over its initial value, minus 1 (0 to rounding for conservative schemes)",
              "solvers that give a density",
              each([optional](const Run& c) { return optional(c.mass_drift); })),
          "0 (conservative schemes)"),
      key(p, "continuum.{solver}.l1_v", "length/time",
          "(1/L) int |v - v_exact| dx: the mean distance to the exact solver per unit length",
          "when the exact solver runs too", each(l1([](const Run& c) { return c.l1_v; }, per_length))),
      key(p, "continuum.{solver}.l1_v_relative", "1",
          "int |v - v_exact| dx / int |v_exact - <v_exact>| dx: against the exact field's variation "
          "about its mean (null: the exact field is constant)",
          "when the exact solver runs too", each(l1([](const Run& c) { return c.l1_v; }, relative))),
      key(p, "continuum.{solver}.l1_rho", "mass/length",
          "(1/L) int |rho - rho_exact| dx: the mean distance to the exact density per unit length",
          "when both give a density", each(l1([](const Run& c) { return c.l1_rho; }, per_length))),
      key(p, "continuum.{solver}.l1_rho_relative", "1",
          "int |rho - rho_exact| dx / int rho_exact dx (at most 2; large wherever a delta-shock is spread "
          "over "
          "other cells than the exact one's, even next to it: continuum.{solver}.w1_rho says where the mass "
          "is)",
          "when both give a density", each(l1([](const Run& c) { return c.l1_rho; }, relative))),
      with_exact_value(
          key(p, "continuum.{solver}.w1_rho", "1",
              "where the mass is: W1 / L = (1/L) min_c int |M - M_exact - c| dx of the cumulative mass "
              "fractions M(x), the mean distance the mass must move as a fraction of the domain "
              "(shockgas/compare/field_distance.hpp)",
              "when both give a density", each([optional](const Run& c) { return optional(c.w1_rho); })),
          "0; a mass fraction f one cell off costs f / cells"),
  };
}

std::vector<Declaration> comparison() {
  const Part p = Part::compare;
  auto cmp = [](auto f) {
    return [f](const RunResults& r, Emitter& out) {
      if (r.comparison) out.json(f(*r.comparison, r.comparison->snapshot));
    };
  };
  using C = Comparison;
  using S = compare::SnapshotComparison;
  return {
      key(p, "compare.note", "", "how the compared states were obtained, if not at t_end",
          "when the particles stopped early",
          [](const RunResults& r, Emitter& out) {
            if (r.comparison && !r.comparison->note.empty()) out.json(r.comparison->note);
          }),
      key(p, "compare.solver", "", "the solver whose shocks are matched (compare.solver)", "",
          cmp([](const C& c, const S&) { return c.solver; })),
      key(p, "compare.t", "time", "time of the compared states", "",
          cmp([](const C&, const S& s) { return s.t; })),
      key(p, "compare.n_shocks", "1", "eligible shocks (mass >= min_mass)", "",
          cmp([](const C&, const S& s) { return s.n_shocks; })),
      key(p, "compare.n_clusters", "1", "eligible clusters (mass >= min_mass)", "",
          cmp([](const C&, const S& s) { return s.n_clusters; })),
      with_theory(key(p, "compare.matched_mass_fraction", "1",
                      "cluster mass matched to a shock / eligible cluster mass", "",
                      cmp([](const C&, const S& s) { return s.match.matched_mass_fraction; })),
                  compare::Law::clusters_are_shocks, "1"),
      key(p, "compare.matched_pairs", "1", "matched shock-cluster pairs", "",
          cmp([](const C&, const S& s) { return s.match.pairs.size(); })),
      key(p, "compare.max_position_error", "length", "largest |x_cluster - x_shock| of a pair", "",
          cmp([](const C&, const S& s) { return s.match.max_position_error; })),
      key(p, "compare.rms_velocity_error", "length/time",
          "root mean square of v_cluster - v_shock over pairs", "",
          cmp([](const C&, const S& s) { return s.match.rms_velocity_error; })),
      key(p, "compare.max_relative_mass_error", "1", "largest |m_cluster - m_shock| / m_cluster of a pair",
          "", cmp([](const C&, const S& s) { return s.match.max_relative_mass_error; })),
      with_theory(
          key(p, "compare.sawtooth_slope_times_t", "1", "median over ramps of the continuum's slope x t", "",
              cmp([](const C&, const S& s) { return s.sawtooth.slope_times_t.median; })),
          compare::Law::ramp_slope, "1"),
      key(p, "compare.sawtooth_slope_times_t_quartiles", "1", "its quartiles", "",
          cmp([](const C&, const S& s) {
            return Json{s.sawtooth.slope_times_t.q25, s.sawtooth.slope_times_t.q75};
          })),
      with_theory(key(p, "compare.particle_sawtooth_slope_times_t", "1",
                      "median over ramps of the particles' slope x t", "",
                      cmp([](const C&, const S& s) { return s.particle_sawtooth.slope_times_t.median; })),
                  compare::Law::ramp_slope, "1"),
      with_theory(key(p, "compare.shock_count_ratio", "1", "n_shocks / (N t^(-2/3))", "",
                      cmp([](const C&, const S& s) { return s.shock_count_ratio; })),
                  compare::Law::shock_count, "O(1), constant in the sticky regime"),
      key(p, "compare.n_shocks_exact", "1",
          "the exact expected number of shocks of mass >= min_mass of Burgers turbulence from this white "
          "noise (shockgas/compare/shock_mass_law.hpp): what n_shocks of hopf_lax and n_clusters of an r = 0 "
          "gas "
          "approach",
          "when the start is white noise on a lattice",
          [](const RunResults& r, Emitter& out) {
            if (r.comparison && r.comparison->n_shocks_exact) out.json(*r.comparison->n_shocks_exact);
          }),
      key(p, "compare.min_mass", "mass",
          "the eligibility threshold: compare.min_cluster_particles mean particle masses", "",
          cmp([](const C&, const S& s) { return s.min_mass; })),
  };
}

std::vector<Declaration> sweep() {
  return {
      key(Part::sweep, "variants", "",
          "one object per variant: label, set (its overrides), directory, summary (its own summary.json)", "",
          [](const RunResults& r, Emitter& out) {
            if (r.variants.empty()) return;
            Json list = Json::array();
            for (const auto& v : r.variants)
              list.push_back(
                  {{"label", v.label}, {"set", v.set}, {"directory", v.directory}, {"summary", v.summary}});
            out.json(list);
          }),
  };
}

}  // namespace

std::vector<Declaration> comparison_keys() {
  std::vector<Declaration> d = continuum();
  append(d, comparison());
  append(d, sweep());
  return d;
}

}  // namespace shockgas::app::layout
