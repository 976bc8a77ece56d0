// The declarations of scene table [compare].
#include "shockgas/compare/params.hpp"

namespace shockgas::compare {

namespace {

ParameterTable<CompareParams> declare() {
  using P = CompareParams;
  ParameterTable<P> t("compare");
  t.add(&P::solver, "solver", "", "the continuum solver whose shocks are matched to the clusters",
        described("one of continuum.solvers"));
  t.add(&P::deposit, "deposit", "", "particles -> grid: nearest cell or cloud in cell");
  t.add(&P::match_distance, "match_distance", "length",
        "largest shock-cluster distance of a match; 0 = automatic", allowed(at_least(0)));
  t.add(&P::min_cluster_particles, "min_cluster_particles", "1",
        "clusters and shocks lighter than this many mean particle masses are not counted; 0 = max(2, "
        "t^(2/3)/10)",
        allowed(at_least(0)));
  t.add(&P::cluster_gap, "cluster_gap", "length",
        "largest gap inside a cluster; 0 = derived from delta and the spacing", allowed(at_least(0)));
  t.add(&P::cluster_dv, "cluster_dv", "length/time",
        "largest relative velocity inside a cluster; 0 = derived from delta", allowed(at_least(0)));
  t.add(&P::distribution_t_min, "distribution_t_min", "time",
        "scaled velocity distributions are compared at sample times >= this", allowed(at_least(0)));
  t.add(&P::fit_window, "fit_window", "1",
        "T(t) is fitted from t_end / fit_window to t_end, and from no earlier than a decade after the "
        "scene's last crossover (10 t_stick for a gas, 10 t* for a wave)",
        allowed(above(1)));
  return t;
}

}  // namespace

const ParameterTable<CompareParams>& parameters() {
  static const ParameterTable<CompareParams> table = declare();
  return table;
}

void validate(const CompareParams& p) { parameters().check(p); }

}  // namespace shockgas::compare
