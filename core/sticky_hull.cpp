// The exact sticky-particle solution by the lower convex hull (E, Rykov & Sinai
// 1996; Brenier & Grenier 1998).
//
// Algorithm. The lower convex hull of the cumulative points (M_k, S_k) is built
// by a monotone chain written in cluster form (pool-adjacent-violators): bodies
// are pushed left to right as one-body clusters, and while the cluster below the
// top of the stack would sit to the right of the top one at time t,
//
//     x_left(t) > x_right(t),   x(t) = (centre of mass at 0) + t * (mean velocity),
//
// the two merge. x(t) is the slope of a hull edge, so this is exactly the
// convexity test of the chain, but it compares positions of neighbouring
// clusters instead of subtracting large cumulative sums S_k, and each cluster's
// centre is stored relative to its first body, so no quantity grows with N.
//
// Ties. The merge test is strict: clusters that exactly touch at t (collinear
// hull points) stay separate; they collide at t and are merged for any later
// time. Hence at t = 0 every body is its own cluster, even bodies that share a
// position. Because exact ties are decided by rounding anyway, this only fixes
// which of two answers that agree in position to rounding is returned.
//
// Ring. After the Galilean shift u -> u - U (U = total momentum / total mass)
// the unrolled chain (copies q + jL, j = -1, 0, 1) has a periodic hull and no
// cluster holds more than N bodies; the hull vertices of the three-period
// window in [N, 2N] are those of the infinite chain, so one period of clusters
// is read off starting at the first cluster boundary a >= N. Differences of
// positions are formed as (q_i2 - q_i1) + (j2 - j1) L, so every period is
// computed with bitwise the same arithmetic; should rounding still make the
// period not close exactly at a + N, the cluster straddling a + N is cut there
// (its two parts then touch to rounding).
#include "shockgas/core/sticky_hull.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "shockgas/core/error.hpp"

namespace shockgas {

namespace {

// A cluster under construction: bodies [first, first + count) of the chain.
struct Run {
  std::size_t first = 0;
  std::size_t count = 0;
  double m = 0;   // mass
  double v = 0;   // velocity (mass-weighted mean)
  double d0 = 0;  // centre of mass at t = 0 minus the first body's position
};

// The open line: body k is initial[k].
struct LineChain {
  const Bodies& b;
  std::size_t size() const { return b.size(); }
  double m(std::size_t k) const { return b.m[k]; }
  double u(std::size_t k) const { return b.v[k]; }
  // q_k2 - q_k1.
  double gap(std::size_t k1, std::size_t k2) const { return b.x[k2] - b.x[k1]; }
  double q(std::size_t k) const { return b.x[k]; }
};

// The ring unrolled over `periods` periods: body k is initial[k mod N] shifted by
// (k / N - 1) L, with the velocity shift u -> u - U.
struct RingChain {
  const Bodies& b;
  double L;
  double U;
  std::size_t periods;
  std::size_t n() const { return b.size(); }
  std::size_t size() const { return periods * n(); }
  double m(std::size_t k) const { return b.m[k % n()]; }
  double u(std::size_t k) const { return b.v[k % n()] - U; }
  double gap(std::size_t k1, std::size_t k2) const {
    const double dj = static_cast<double>(k2 / n()) - static_cast<double>(k1 / n());
    return (b.x[k2 % n()] - b.x[k1 % n()]) + dj * L;
  }
  double q(std::size_t k) const {
    return b.x[k % n()] + (static_cast<double>(k / n()) - 1.0) * L;
  }
};

// Whether `left` would be to the right of `right` at time t (strictly).
template <class Chain>
bool overlaps(const Chain& c, const Run& left, const Run& right, double t) {
  const double xl = left.d0 + t * left.v;
  const double xr = c.gap(left.first, right.first) + right.d0 + t * right.v;
  return xl > xr;
}

// Perfectly inelastic merge of right into left: mass and momentum add.
template <class Chain>
void absorb(const Chain& c, Run& left, const Run& right) {
  const double m = left.m + right.m;
  const double dq = c.gap(left.first, right.first);
  left.d0 += (right.m / m) * (dq + right.d0 - left.d0);
  left.v = (left.m * left.v + right.m * right.v) / m;
  left.m = m;
  left.count += right.count;
}

// The hull of the whole chain as a stack of runs, left to right. O(size).
template <class Chain>
std::vector<Run> hull_runs(const Chain& c, double t) {
  std::vector<Run> stack;
  stack.reserve(64);
  for (std::size_t k = 0; k < c.size(); ++k) {
    Run top{k, 1, c.m(k), c.u(k), 0.0};
    while (!stack.empty() && overlaps(c, stack.back(), top, t)) {
      Run left = stack.back();
      stack.pop_back();
      absorb(c, left, top);
      top = left;
    }
    stack.push_back(top);
  }
  return stack;
}

// One run recomputed directly from its bodies [first, first + count), count >= 1.
template <class Chain>
Run summarise(const Chain& c, std::size_t first, std::size_t count) {
  Run r{first, 1, c.m(first), c.u(first), 0.0};
  for (std::size_t k = first + 1; k < first + count; ++k) absorb(c, r, Run{k, 1, c.m(k), c.u(k), 0.0});
  return r;
}

void check_bodies(const Bodies& b, double t) {
  require_in_range("t", t, 0.0, std::numeric_limits<double>::max());
  require(b.v.size() == b.size() && b.m.size() == b.size(), "bodies", b.size(),
          "x, v and m of equal length");
  for (std::size_t i = 0; i < b.size(); ++i) {
    require(std::isfinite(b.x[i]) && std::isfinite(b.v[i]), "bodies.x/v", b.x[i], "finite values");
    require(b.m[i] > 0 && std::isfinite(b.m[i]), "bodies.m", b.m[i], "finite masses > 0");
    if (i > 0) require(b.x[i] >= b.x[i - 1], "bodies.x", b.x[i], "positions sorted ascending");
  }
}

double wrap(double x, double L) {
  double w = std::fmod(x, L);
  if (w < 0) w += L;
  return w >= L ? 0.0 : w;
}

// The ring's runs of one period, starting at the first boundary >= N.
std::vector<Run> one_period(const RingChain& c, const std::vector<Run>& runs) {
  const std::size_t n = c.n();
  auto it = std::find_if(runs.begin(), runs.end(), [&](const Run& r) { return r.first >= n; });
  if (it == runs.end() || it->first >= 2 * n) return {summarise(c, n, n)};  // one run spans [N, 2N]
  const std::size_t a = it->first;
  std::vector<Run> period;
  for (; it != runs.end() && it->first < a + n; ++it) {
    if (it->first + it->count <= a + n)
      period.push_back(*it);
    else
      period.push_back(summarise(c, it->first, a + n - it->first));  // cut at a + N (rounding)
  }
  return period;
}

}  // namespace

std::vector<StickyCluster> sticky_clusters_line(const Bodies& initial, double t) {
  check_bodies(initial, t);
  const LineChain c{initial};
  std::vector<StickyCluster> out;
  for (const Run& r : hull_runs(c, t))
    out.push_back({c.q(r.first) + r.d0 + t * r.v, r.v, r.m, r.first, r.count});
  return out;
}

std::vector<StickyCluster> sticky_clusters_ring(const Bodies& initial, double L, double t) {
  check_bodies(initial, t);
  require_above("L", L, 0.0);
  const std::size_t n = initial.size();
  if (n == 0) return {};
  require(initial.x.front() >= 0 && initial.x.back() < L, "bodies.x", initial.x.back(),
          "positions in [0, L)");
  const double U = total_momentum(initial) / total_mass(initial);
  const RingChain c{initial, L, U, 3};
  std::vector<StickyCluster> out;
  for (const Run& r : one_period(c, hull_runs(c, t)))
    out.push_back({wrap(c.q(r.first) + r.d0 + t * (r.v + U), L), r.v + U, r.m, r.first % n, r.count});
  // The period is in cyclic order of x; rotate it so that x ascends.
  auto lowest = std::min_element(out.begin(), out.end(),
                                 [](const StickyCluster& a, const StickyCluster& b) { return a.x < b.x; });
  std::rotate(out.begin(), lowest, out.end());
  return out;
}

Bodies to_bodies(const std::vector<StickyCluster>& clusters) {
  std::vector<std::size_t> order(clusters.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return clusters[a].x < clusters[b].x; });
  Bodies b;
  b.reserve(clusters.size());
  for (std::size_t i : order) b.push_back(clusters[i].x, clusters[i].v, clusters[i].m);
  return b;
}

}  // namespace shockgas
