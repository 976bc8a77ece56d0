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
// clusters instead of subtracting large cumulative sums S_k. O(N), one pass.
//
// Ties. The merge test is strict: clusters that exactly touch at t (collinear
// hull points) stay separate; they collide at t and are merged for any later
// time. Hence at t = 0 every body is its own cluster, even bodies that share a
// position. Because exact ties are decided by rounding anyway, this only fixes
// which of two answers that agree in position to rounding is returned.
//
// Ring. After the Galilean shift u -> u - U (U = total momentum / total mass)
// the periodically unrolled chain (body i + N is body i moved by L) has a
// periodic hull, and no cluster holds more than N bodies. With
// s = centre of mass and phi(k) = S_k - s M_k one finds
// phi(k + N) - phi(k) = L M_k >= 0 and phi(k - N) - phi(k) = L (M - M_k) >= 0,
// so the minimiser k* of phi over one period is a hull vertex of the infinite
// chain (a supporting line of slope s touches it). One period is then a line
// problem: bodies k*, ..., N-1, then 0, ..., k*-1 moved by L. Should rounding in
// phi pick a point just above the hull, the two runs meeting at the seam
// overlap; they are merged across it (and cascaded), which restores the hull.
#include "shockgas/core/sticky_hull.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "shockgas/core/error.hpp"

namespace shockgas {

namespace {

// A cluster: chain positions [first, first + count).
struct Run {
  double c0;          // centre of mass at t = 0 (chain coordinates)
  double v;           // velocity (mass-weighted mean)
  double m;           // mass
  std::size_t first;  // chain position of its first body
  std::size_t count;  // number of bodies
};

// Whether `left` would be to the right of `right` at time t (strictly).
bool overlaps(const Run& left, const Run& right, double t) {
  return left.c0 + t * left.v > right.c0 + t * right.v;
}

// Perfectly inelastic merge: mass and momentum add.
Run merged(const Run& left, const Run& right) {
  const double m = left.m + right.m;
  return {left.c0 + (right.m / m) * (right.c0 - left.c0), (left.m * left.v + right.m * right.v) / m, m,
          left.first, left.count + right.count};
}

// The monotone chain in cluster form; bodies are pushed left to right.
class HullStack {
 public:
  HullStack(std::size_t n, double t) : t_(t) { runs_.reserve(n); }
  void push(double q, double u, double m) {
    Run top{q, u, m, pushed_++, 1};
    while (!runs_.empty() && overlaps(runs_.back(), top, t_)) {
      top = merged(runs_.back(), top);
      runs_.pop_back();
    }
    runs_.push_back(top);
  }
  std::vector<Run>& runs() { return runs_; }

 private:
  double t_;
  std::size_t pushed_ = 0;
  std::vector<Run> runs_;
};

void check_bodies(const Bodies& b, double t) {
  require_in_range("t", t, 0.0, std::numeric_limits<double>::max());
  require(b.v.size() == b.size() && b.m.size() == b.size(), "bodies", b.size(),
          "x, v and m of equal length");
  for (std::size_t i = 0; i < b.size(); ++i) {
    if (!(std::isfinite(b.x[i]) && std::isfinite(b.v[i])))
      throw InputError("bodies.x/v", to_text(b.x[i]) + ", " + to_text(b.v[i]), "finite values");
    if (!(b.m[i] > 0 && std::isfinite(b.m[i]))) throw InputError("bodies.m", to_text(b.m[i]), "finite masses > 0");
    if (i > 0 && !(b.x[i] >= b.x[i - 1]))
      throw InputError("bodies.x", to_text(b.x[i]), "positions sorted ascending");
  }
}

double wrap(double x, double L) {
  double w = std::fmod(x, L);
  if (w < 0) w += L;
  return w >= L ? 0.0 : w;
}

// The start k* of the ring's period: the minimiser of
// phi(k) = sum_{i<k} m_i (x_i + t u_i - s), s the centre of mass.
std::size_t seam(const Bodies& b, double U, double t) {
  const double M = total_mass(b);
  double s = 0;
  for (std::size_t i = 0; i < b.size(); ++i) s += b.m[i] * b.x[i] / M;
  double phi = 0, best = 0;
  std::size_t at = 0;
  for (std::size_t k = 0; k < b.size(); ++k) {
    if (phi < best) best = phi, at = k;
    phi += b.m[k] * ((b.x[k] - s) + t * (b.v[k] - U));
  }
  return at;
}

// Merges runs across the seam while the last one (chain end) would be to the
// right of the first one moved by one period; cascades on both sides.
void close_ring(std::vector<Run>& runs, double L, double t) {
  std::size_t front = 0;
  auto shifted = [&](const Run& r) { return Run{r.c0 + L, r.v, r.m, r.first, r.count}; };
  for (;;) {
    if (runs.size() - front >= 2 && overlaps(runs.back(), shifted(runs[front]), t)) {
      runs.back() = merged(runs.back(), shifted(runs[front]));
      ++front;
    } else if (runs.size() - front >= 2 && overlaps(runs[runs.size() - 2], runs.back(), t)) {
      runs[runs.size() - 2] = merged(runs[runs.size() - 2], runs.back());
      runs.pop_back();
    } else {
      break;
    }
  }
  runs.erase(runs.begin(), runs.begin() + static_cast<std::ptrdiff_t>(front));
}

}  // namespace

std::vector<StickyCluster> sticky_clusters_line(const Bodies& initial, double t) {
  check_bodies(initial, t);
  HullStack hull(initial.size(), t);
  for (std::size_t i = 0; i < initial.size(); ++i) hull.push(initial.x[i], initial.v[i], initial.m[i]);
  std::vector<StickyCluster> out;
  out.reserve(hull.runs().size());
  for (const Run& r : hull.runs()) out.push_back({r.c0 + t * r.v, r.v, r.m, r.first, r.count});
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
  const std::size_t k0 = seam(initial, U, t);
  HullStack hull(n, t);
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t i = k0 + k < n ? k0 + k : k0 + k - n;
    hull.push(initial.x[i] + (k0 + k < n ? 0.0 : L), initial.v[i] - U, initial.m[i]);
  }
  close_ring(hull.runs(), L, t);
  std::vector<StickyCluster> out;
  out.reserve(hull.runs().size());
  for (const Run& r : hull.runs())
    out.push_back({wrap(r.c0 + t * r.v + U * t, L), r.v + U, r.m, (k0 + r.first) % n, r.count});
  // The period is in cyclic order of x; rotate it so that x ascends.
  auto lowest = std::min_element(out.begin(), out.end(),
                                 [](const StickyCluster& a, const StickyCluster& b) { return a.x < b.x; });
  std::rotate(out.begin(), lowest, out.end());
  return out;
}

Bodies to_bodies(const std::vector<StickyCluster>& clusters) {
  const auto by_x = [](const StickyCluster& a, const StickyCluster& b) { return a.x < b.x; };
  Bodies b;
  b.reserve(clusters.size());
  if (std::is_sorted(clusters.begin(), clusters.end(), by_x)) {  // what the solvers return
    for (const StickyCluster& c : clusters) b.push_back(c.x, c.v, c.m);
    return b;
  }
  std::vector<std::size_t> order(clusters.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t i, std::size_t j) { return by_x(clusters[i], clusters[j]); });
  for (std::size_t i : order) b.push_back(clusters[i].x, clusters[i].v, clusters[i].m);
  return b;
}

}  // namespace shockgas
