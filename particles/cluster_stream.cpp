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

namespace shockgas::particles {

namespace {

// One cluster's sums as make_cluster takes them: members in order from its first.
class ClusterSums {
 public:
  void start(std::size_t first, double x, double v) {
    k_ = {first, 0, 0.0, 0.0, 0.0};
    x_first_ = x, v_first_ = v, m_dx_ = 0, mv_ = 0;
  }
  void add(double x, double v, double m) {  // x unrolled past the wrap
    k_.m += m;
    m_dx_ += m * (x - x_first_);
    mv_ += m * v;
    ++k_.count;
  }
  Cluster done(double L) const {
    Cluster k = k_;
    k.x = x_first_ + m_dx_ / k.m;
    k.v = k.count == 1 ? v_first_ : mv_ / k.m;
    if (L > 0) {
      k.x = std::fmod(k.x, L);
      if (k.x < 0) k.x += L;
      if (k.x >= L) k.x = 0.0;  // rounding of fmod near L
    }
    return k;
  }

 private:
  Cluster k_;
  double x_first_ = 0, v_first_ = 0, m_dx_ = 0, mv_ = 0;
};

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
  require(std::isfinite(L) && L >= 0, "cluster.L", L, "L >= 0 (0 = open line)");
  require(std::isfinite(c.max_gap) && c.max_gap >= 0, "cluster.max_gap", c.max_gap, "finite, >= 0");
  require(std::isfinite(c.max_dv) && c.max_dv >= 0, "cluster.max_dv", c.max_dv, "finite, >= 0");
  if (state.size() == 0) return;
  const std::size_t start = L > 0 ? ring_start(state, L, c) : 0;
  ClusterSums sums;
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
