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
    first_ = first, count_ = 0, m_ = 0;
    x_first_ = x, v_first_ = v, m_dx_ = 0, mv_ = 0;
  }
  void add(double x, double v, double m) {  // x unrolled past the wrap
    m_ += m;
    m_dx_ += m * (x - x_first_);
    mv_ += m * v;
    ++count_;
  }
  double mass() const { return m_; }
  // x = x_first + sum m (x - x_first) / M, v = sum m v / M. One body: its m_dx
  // is +0 (m finite), so x is x_first + 0 without the division, the same bits.
  Cluster done(double L) const {
    Cluster k{first_, count_, 0.0, v_first_, m_};
    if (count_ == 1) {
      k.x = x_first_ + 0.0;
    } else {
      k.x = x_first_ + m_dx_ / m_;
      k.v = mv_ / m_;
    }
    if (L > 0 && !(k.x >= 0 && k.x < L)) {  // fmod gives x itself on [0, L)
      k.x = std::fmod(k.x, L);
      if (k.x < 0) k.x += L;
      if (k.x >= L) k.x = 0.0;  // rounding of fmod near L
    }
    return k;
  }

 private:
  // Scalars, not a Cluster: done() reads them right after add() wrote them,
  // and a wide copy of a struct just written one field at a time stalls.
  std::size_t first_ = 0, count_ = 0;
  double m_ = 0, x_first_ = 0, v_first_ = 0, m_dx_ = 0, mv_ = 0;
};

// The checks of L and of the criteria both walks make.
inline void require_cluster_inputs(double L, const ClusterCriteria& c) {
  require(std::isfinite(L) && L >= 0, "cluster.L", L, "L >= 0 (0 = open line)");
  require(std::isfinite(c.max_gap) && c.max_gap >= 0, "cluster.max_gap", c.max_gap, "finite, >= 0");
  require(std::isfinite(c.max_dv) && c.max_dv >= 0, "cluster.max_dv", c.max_dv, "finite, >= 0");
}

}  // namespace shockgas::particles::detail
