#pragma once
// One cluster's mass, centre of mass and velocity from its members taken in
// order from its first (a member past the ring's end unrolled by +L): the one
// rule find_clusters (a whole copy) and visit_clusters (a state read in chunks)
// share, so that both give the same bits. The centre is taken relative to the
// first member, so a one-body cluster sits exactly on its body.
#include <cmath>

#include "shockgas/core/error.hpp"
#include "shockgas/particles/cluster_finder.hpp"

namespace shockgas::particles::detail {

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
  Cluster k_{};
  double x_first_ = 0, v_first_ = 0, m_dx_ = 0, mv_ = 0;
};

// The checks of L and of the criteria both walks make.
inline void require_cluster_inputs(double L, const ClusterCriteria& c) {
  require(std::isfinite(L) && L >= 0, "cluster.L", L, "L >= 0 (0 = open line)");
  require(std::isfinite(c.max_gap) && c.max_gap >= 0, "cluster.max_gap", c.max_gap, "finite, >= 0");
  require(std::isfinite(c.max_dv) && c.max_dv >= 0, "cluster.max_dv", c.max_dv, "finite, >= 0");
}

}  // namespace shockgas::particles::detail
