// The clusters of a state read in chunks (cluster_finder.hpp: visit_clusters),
// as find_clusters finds them from a whole copy: the same walk, the same sums in
// the same order, so the same bits.
//
// find_clusters starts the walk at the first body whose left neighbour is not
// joined to it (ring), so the cluster across the wrap comes last and sums its
// members from its first body past N - 1 round to the start. Streamed: a first
// read finds the start; a second walks from it to N - 1; a third adds the
// bodies before the start (unrolled by + L) to the last cluster.
#include <limits>

#include "shockgas/core/error.hpp"
#include "shockgas/particles/cluster_finder.hpp"
#include "shockgas/particles/cluster_sums.hpp"

namespace shockgas::particles {

namespace {

// Visits body i of the state with f(i, x, v, m), in order.
template <class F>
void each_body(const StateReader& state, F&& f) {
  std::size_t i = 0;
  state.read([&](const double* x, const double* v, const double* m, std::size_t count) {
    for (std::size_t k = 0; k < count; ++k, ++i) f(i, x[k], v[k], m[k]);
  });
}

// Where find_clusters starts on a ring: the first body not joined to its left
// neighbour (body 0's is body N - 1, across the wrap), else 0.
std::size_t ring_start(const StateReader& state, double L, const ClusterCriteria& c) {
  const std::size_t n = state.size();
  if (n < 2) return 0;
  std::size_t first_break = 0;  // none yet
  double x0 = 0, v0 = 0, x_last = 0, v_last = 0;
  each_body(state, [&](std::size_t i, double x, double v, double) {
    if (i == 0) x0 = x, v0 = v;
    if (i > 0 && first_break == 0 && !c.joins(x - x_last, v - v_last)) first_break = i;
    x_last = x, v_last = v;
  });
  return c.joins(x0 + L - x_last, v0 - v_last) ? first_break : 0;
}

}  // namespace

void visit_clusters(const StateReader& state, double L, const ClusterCriteria& c,
                    const std::function<void(const Cluster&)>& visit) {
  detail::require_cluster_inputs(L, c);
  if (state.size() == 0) return;
  const std::size_t start = L > 0 ? ring_start(state, L, c) : 0;
  detail::ClusterSums sums;
  double x_last = 0, v_last = 0;
  each_body(state, [&](std::size_t i, double x, double v, double m) {
    if (i < start) return;
    if (i == start) {
      sums.start(i, x, v);
    } else if (!c.joins(x - x_last, v - v_last)) {
      visit(sums.done(L));
      sums.start(i, x, v);
    }
    sums.add(x, v, m);
    x_last = x, v_last = v;
  });
  if (start > 0)  // the last cluster runs on across the wrap up to the start
    each_body(state, [&](std::size_t i, double x, double v, double m) {
      if (i < start) sums.add(x + L, v, m);
    });
  visit(sums.done(L));
}

}  // namespace shockgas::particles
