// The exact adhesion (Hopf-Lax) field of point masses on a ring; see hopf_lax.hpp.
//
// Lagrangian cells. Body i (positions x_0 <= ... <= x_{N-1} in [0, L)) owns the
// Lagrangian interval [b_i, b_{i+1}] between the midpoints to its neighbours,
//     b_i = (x_{i-1} + x_i) / 2,   x_{-1} = x_{N-1} - L,   b_{i+N} = b_i + L,
// the Voronoi picture that also makes N lattice particles the cell averages of
// an N-cell grid. A cluster of the bodies first, ..., last (one hull edge of
// sticky_clusters_ring) owns [q_L, q_R] = [b_first, b_{last+1}].
//
// The field at t > 0. The shocks are the clusters: position x_c and velocity
// V_c from the hull, mass the cluster's. Between consecutive clusters c and c+1
// lies vacuum whose Lagrangian preimage is the single point q_R(c) = q_L(c+1),
// so there (docs/design.md §1)
//     v(x, t) = (x - q_R(c)) / t,                                    (1)
// a ramp of slope exactly 1/t, and at cluster c the velocity jumps by
//     v(x_c+) - v(x_c-) = (q_L(c) - q_R(c)) / t < 0.                 (2)
// x in (1) must be x_c's unwrapped lab-frame position. The cluster's centre of
// mass moves ballistically, x_c = X_c + V_c t (X_c its centre of mass at t = 0
// in the same unwrapped chain coordinates as q_L, q_R), so (1) is evaluated as
//     v(x) = V_c + (X_c - q_R(c)) / t + (x - x_c) / t,               (3)
// where X_c - q_R(c) is a local difference (no period count, no cancellation
// against a large U t) and x - x_c is measured on the ring from the hull's x_c.
//
// Cell averages. The velocity is integrated ramp by ramp,
//     int_s^e v = (e - s) (a + ((s + e)/2 - x_c) / t),   a = v(x_c+),
// split at every cluster inside a cell (a delta mass adds nothing to int v).
// The density is the clusters' masses over dx in the cell [i dx, (i+1) dx)
// that holds x_c (a cluster exactly on an edge counts to the cell on its
// right, the rule of continuum::cell_averages), zero in vacuum.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "shockgas/continuum/hopf_lax.hpp"
#include "shockgas/core/error.hpp"
#include "shockgas/core/sticky_hull.hpp"

namespace shockgas::continuum {

namespace {

// Bodies on the unrolled ring: chain index k = j + p N is body j moved by p L.
class Chain {
 public:
  Chain(const Bodies& b, double L) : b_(b), L_(L), n_(b.size()) {}
  double position(std::size_t k) const { return b_.x[k % n_] + period(k) * L_; }
  double mass(std::size_t k) const { return b_.m[k % n_]; }
  // b_k: the left edge of body k's Lagrangian cell.
  double boundary(std::size_t k) const {
    const std::size_t j = k % n_;
    const double left = j > 0 ? b_.x[j - 1] : b_.x[n_ - 1] - L_;
    return 0.5 * (left + b_.x[j]) + period(k) * L_;
  }

 private:
  // The whole periods in k (integer division: body k lies in period k / n).
  double period(std::size_t k) const {
    const std::size_t whole = k / n_;
    return static_cast<double>(whole);
  }
  const Bodies& b_;
  double L_;
  std::size_t n_;
};

// One cluster seen from the field: where it is and the velocity on either side.
struct Tooth {
  double x;        // position in [0, L) (the hull's)
  double m;        // mass
  double v;        // velocity (momentum / mass)
  double v_right;  // v(x+) = (x - q_R) / t, by (3)
  double jump;     // v(x+) - v(x-) = (q_L - q_R) / t
  std::size_t count;
};

std::vector<Tooth> teeth(const Bodies& b, double L, double t, const std::vector<StickyCluster>& clusters) {
  const Chain chain(b, L);
  std::vector<Tooth> out;
  out.reserve(clusters.size());
  for (const StickyCluster& c : clusters) {
    const double qL = chain.boundary(c.first), qR = chain.boundary(c.first + c.count);
    double m = 0, moment = 0;  // sum m_i, sum m_i (x_i - q_R)
    for (std::size_t k = c.first; k < c.first + c.count; ++k) {
      m += chain.mass(k);
      moment += chain.mass(k) * (chain.position(k) - qR);
    }
    out.push_back({c.x, c.m, c.v, c.v + (moment / m) / t, (qL - qR) / t, c.count});
  }
  return out;
}

// int_s^e of the ramp of slope 1/t through (origin, a).
double ramp_integral(double s, double e, double origin, double a, double t) {
  return (e - s) * (a + (0.5 * (s + e) - origin) / t);
}

// Cell averages of the sawtooth of `teeth` (sorted by x in [0, L)).
CellAverages sawtooth_averages(const std::vector<Tooth>& teeth, double L, std::size_t cells, double t) {
  CellAverages a{std::vector<double>(cells, 0.0), std::vector<double>(cells, 0.0)};
  const double dx = L / static_cast<double>(cells);
  for (const Tooth& c : teeth) {
    const std::size_t i = std::min(cells - 1, static_cast<std::size_t>(c.x / dx));
    a.rho[i] += c.m / dx;
  }
  // [0, x_0) is the end of the ramp right of the last cluster, one period back.
  double origin = teeth.back().x - L, level = teeth.back().v_right;
  std::size_t next = 0;
  for (std::size_t i = 0; i < cells; ++i) {
    double s = static_cast<double>(i) * dx, sum = 0;
    const double e = i + 1 < cells ? static_cast<double>(i + 1) * dx : L;
    for (; next < teeth.size() && teeth[next].x < e; ++next) {
      const double x = std::max(s, teeth[next].x);
      sum += ramp_integral(s, x, origin, level, t);
      s = x;
      origin = teeth[next].x, level = teeth[next].v_right;
    }
    sum += ramp_integral(s, e, origin, level, t);
    a.v[i] = sum / (e - static_cast<double>(i) * dx);
  }
  return a;
}

}  // namespace

ContinuumResult hopf_lax_point_masses(const InitialField& f, std::size_t cells, double t) {
  require(cells >= 1, "continuum.cells", cells, ">= 1");
  require_in_range("t", t, 0.0, std::numeric_limits<double>::max());
  require_above("initial.domain", f.length, 0.0);
  const Bodies& b = f.bodies;
  ContinuumResult r;
  r.stats = {{"bodies", static_cast<double>(b.size())}};
  if (b.size() == 0 || t == 0) {
    // No ramps to draw: at t = 0 their slope 1/t is infinite; the data are the deposit.
    const CellAverages a = cell_averages(f, cells);
    r.v = a.v;
    r.rho = a.rho;
    r.method_note = "exact: point masses at t = 0, deposited on the grid";
    return r;
  }
  const std::vector<Tooth> all = teeth(b, f.length, t, sticky_clusters_ring(b, f.length, t));
  const CellAverages a = sawtooth_averages(all, f.length, cells, t);
  r.v = a.v;
  r.rho = a.rho;
  for (const Tooth& c : all)
    if (c.count >= 2) r.shocks.push_back({c.x, c.m, c.jump, c.v});
  r.method_note = "exact: adhesion field of " + std::to_string(b.size()) +
                  " point masses, shocks the sticky-particle hull's clusters, ramps (x - q)/t between them";
  r.stats["clusters"] = static_cast<double>(all.size());
  r.stats["shocks"] = static_cast<double>(r.shocks.size());
  return r;
}

}  // namespace shockgas::continuum
