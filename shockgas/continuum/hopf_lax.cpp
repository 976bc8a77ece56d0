// The exact inviscid solution by the Legendre transform; see hopf_lax.hpp.
//
// Accuracy. Psi0 and M0 at the sample nodes are cumulative 4-point
// Gauss-Legendre integrals (compensated sums), exact to rounding for smooth
// data and for data whose kinks or jumps sit on sample nodes. The sampled hull
// gives each minimiser to within one sample; it is then refined on the exact
// characteristic equation q + t w0(q) = y by a bracketed Illinois iteration (to
// a few ulp, also across jumps of v0, where the minimiser is the jump itself),
// and near a shock both sides are refined and the lower Psi wins. Psi is
// stationary at q*, so its value is insensitive to the remaining error in q*.
#include "shockgas/continuum/hopf_lax.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <limits>

#include "shockgas/core/error.hpp"
#include "shockgas/core/sticky_hull.hpp"

namespace shockgas::continuum {

namespace {

// 4-point Gauss-Legendre on [-1, 1] (exact for degree 7).
// Nodes sqrt(3/7 -+ (2/7) sqrt(6/5)), weights (18 +- sqrt 30) / 36.
constexpr std::array<double, 4> kNodes = {-0.86113631159405258, -0.33998104358485626, 0.33998104358485626,
                                          0.86113631159405258};
constexpr std::array<double, 4> kWeights = {0.34785484513745385, 0.65214515486254614, 0.65214515486254614,
                                            0.34785484513745385};

// int_a^b f by one 4-point Gauss-Legendre rule.
template <class F>
double gauss(const F& f, double a, double b) {
  const double mid = 0.5 * (a + b), half = 0.5 * (b - a);
  double s = 0;
  for (std::size_t k = 0; k < kNodes.size(); ++k) s += kWeights[k] * f(mid + half * kNodes[k]);
  return half * s;
}

// Kahan-compensated running sum.
struct CompensatedSum {
  double sum = 0, carry = 0;
  void add(double x) {
    const double y = x - carry;
    const double s = sum + y;
    carry = (s - sum) - y;
    sum = s;
  }
};

// Root of f on [a, b], f(a) <= 0 <= f(b): false position with the
// Anderson-Bjorck weighting of the endpoint kept twice (order ~1.7), each new
// point kept at least tol inside the bracket so that the bracket itself
// collapses. Stops at a point where |f| <= f_noise (the rounding level of f).
// Tolerates jumps of f (converges to the jump). evals counts calls.
template <class F>
double bracketed_root(const F& f, double a, double fa, double b, double fb, double scale, double f_noise,
                      std::size_t& evals) {
  const double eps = std::numeric_limits<double>::epsilon();
  int side = 0;  // -1: a was replaced last, +1: b was
  for (int it = 0; it < 200 && fa != 0 && fb != 0; ++it) {
    const double width = b - a;
    const double tol = 2 * eps * std::max({std::abs(a), std::abs(b), scale});
    if (width <= 2 * tol) break;
    double c = a - fa * (width / (fb - fa));
    if (!(c > a && c < b)) c = a + 0.5 * width;
    c = std::clamp(c, a + tol, b - tol);
    const double fc = f(c);
    ++evals;
    if (std::abs(fc) <= f_noise) return c;
    if (fc <= 0) {
      if (side == -1) {
        const double m = 1 - fc / fa;
        fb *= m > 0 ? m : 0.5;
      }
      a = c, fa = fc, side = -1;
    } else {
      if (side == 1) {
        const double m = 1 - fc / fb;
        fa *= m > 0 ? m : 0.5;
      }
      b = c, fb = fc, side = 1;
    }
  }
  if (fa == 0) return a;
  if (fb == 0) return b;
  return 0.5 * (a + b);
}

}  // namespace

HopfLaxSolution::HopfLaxSolution(const InitialField& f, double t, std::size_t samples)
    : v0_(f.v0), rho0_(f.rho0), t_(t), L_(f.length), n_(samples) {
  require(static_cast<bool>(f.v0), "initial.v0", std::string("(none)"),
          "pointwise v0 (point masses go through solve_hopf_lax)");
  require_above("initial.domain", f.length, 0.0);
  require_in_range("t", t, 0.0, std::numeric_limits<double>::max());
  require(samples >= 16, "hopf_lax.samples", samples, ">= 16");
  h_ = L_ / static_cast<double>(n_);
  build_tables();
  if (t_ > 0) build_hull();
}

std::size_t HopfLaxSolution::node_index(long node) const {
  const long n = static_cast<long>(n_);
  return static_cast<std::size_t>(((node % n) + n) % n);
}

long HopfLaxSolution::node_period(long node) const {
  return (node - static_cast<long>(node_index(node))) / static_cast<long>(n_);
}

long HopfLaxSolution::node_below(double q) const { return static_cast<long>(std::floor(q / h_)); }

double HopfLaxSolution::wrap(double q) const {
  if (q >= 0 && q < L_) return q;
  const double w = q - L_ * std::floor(q / L_);
  return (w >= 0 && w < L_) ? w : 0.0;  // w == L_ only by rounding of q just below 0
}

double HopfLaxSolution::v0(double q) const {
  ++evaluations_;
  return v0_(wrap(q));
}

double HopfLaxSolution::rho0(double q) const { return rho0_ ? rho0_(wrap(q)) : 1.0; }

// Psi0_w = int (v0 - U) and M0 at the nodes j h, j < n. v0 - U0 is integrated
// with a first estimate U0 (midpoint mean) so that a large mean velocity does
// not cancel digits of Psi0_w; the residual mean is removed afterwards.
void HopfLaxSolution::build_tables() {
  psi_.resize(n_);
  mcum_.resize(n_);
  const std::size_t coarse = 256;
  double u0 = 0;
  for (std::size_t i = 0; i < coarse; ++i) u0 += v0((static_cast<double>(i) + 0.5) * L_ / coarse) / coarse;
  if (!std::isfinite(u0)) u0 = 0;  // the fine pass names the offending point
  CompensatedSum p, m;
  for (std::size_t j = 0; j < n_; ++j) {
    psi_[j] = p.sum;
    mcum_[j] = m.sum;
    const double a = node_q(static_cast<long>(j)), b = node_q(static_cast<long>(j) + 1);
    const double dp = gauss([&](double q) { return v0(q) - u0; }, a, b);
    const double dm = gauss([&](double q) { return rho0(q); }, a, b);
    if (!std::isfinite(dp))
      throw InputError("initial.v0", "non-finite near x = " + to_text(a), "finite values");
    if (!(dm >= 0 && std::isfinite(dm)))
      throw InputError("initial.rho0", to_text(dm / h_) + " near x = " + to_text(a), "finite values >= 0");
    p.add(dp);
    m.add(dm);
  }
  const double residual = p.sum / L_;
  U_ = u0 + residual;
  mass_ = m.sum;
  for (std::size_t j = 0; j < n_; ++j) psi_[j] -= residual * node_q(static_cast<long>(j));
}

// The lower hull of (q_j, g(q_j)), g = q^2/2 + t Psi0_w: the sticky hull of one
// period of samples (sticky_clusters_ring), its edges in chain order with
// unwrapped slopes, listed over three periods so that every y in [0, L) lies
// between two listed edges (a minimiser lies within L/2 of its y: its periodic
// copies are farther).
void HopfLaxSolution::build_hull() {
  Bodies samples;
  samples.reserve(n_);
  for (std::size_t j = 0; j < n_; ++j) {
    const double dpsi = (j + 1 < n_ ? psi_[j + 1] : psi_[0]) - psi_[j];
    samples.push_back((static_cast<double>(j) + 0.5) * h_, dpsi / h_, h_);
  }
  std::vector<StickyCluster> hull = sticky_clusters_ring(samples, L_, t_);
  std::rotate(hull.begin(),
              std::min_element(hull.begin(), hull.end(), [](auto& a, auto& b) { return a.first < b.first; }),
              hull.end());
  period_edges_ = hull.size();
  const long n = static_cast<long>(n_);
  const auto psi_node = [&](long node) { return psi_[node_index(node)]; };
  for (long k = -1; k <= 1; ++k) {
    for (const StickyCluster& c : hull) {
      const long a = static_cast<long>(c.first) + k * n, b = a + static_cast<long>(c.count);
      hull_x_.push_back(0.5 * (node_q(a) + node_q(b)) +
                        t_ * (psi_node(b) - psi_node(a)) / (node_q(b) - node_q(a)));
      hull_start_.push_back(a);
    }
  }
  hull_start_.push_back(static_cast<long>(hull.back().first + hull.back().count) + n);
}

// Psi0_w(q) from the nearest node below and one quadrature over less than a sample.
double HopfLaxSolution::psi0(double q) const {
  const long j = node_below(q);
  return psi_[node_index(j)] + gauss([&](double s) { return v0(s) - U_; }, node_q(j), q);
}

double HopfLaxSolution::m0(double q) const {
  const long j = node_below(q);
  return mcum_[node_index(j)] + static_cast<double>(node_period(j)) * mass_ +
         gauss([&](double s) { return rho0(s); }, node_q(j), q);
}

// The root of q + t w0(q) = y next to node, bracketed between the node and a
// neighbour; bracketed = false if the three samples show no sign change.
double HopfLaxSolution::root_near(double y, long node, bool& bracketed) const {
  const auto f = [&](double q) { return q + t_ * (v0(q) - U_) - y; };
  const double q0 = node_q(node), f0 = f(q0);
  // Rounding of f's terms q, t w0 = f + y - q and y.
  const double noise =
      4 * std::numeric_limits<double>::epsilon() * (std::abs(q0) + std::abs(f0 + y - q0) + std::abs(y) + h_);
  bracketed = true;
  if (f0 >= 0) {
    const double qm = node_q(node - 1), fm = f(qm);
    if (fm <= 0) return bracketed_root(f, qm, fm, q0, f0, h_, noise, evaluations_);
  } else {
    const double qp = node_q(node + 1), fp = f(qp);
    if (fp >= 0) return bracketed_root(f, q0, f0, qp, fp, h_, noise, evaluations_);
  }
  bracketed = false;
  return q0;
}

HopfLaxSolution::Minimum HopfLaxSolution::refine(double y, long node) const {
  const auto F = [&](double q) { return (y - q) * (y - q) / (2 * t_) + psi0(q); };
  bool bracketed = false;
  double q = root_near(y, node, bracketed);
  if (!bracketed) {
    ++unbracketed_;
    for (long j : {node - 1, node + 1})
      if (F(node_q(j)) < F(q)) q = node_q(j);
  }
  return {q, F(q)};
}

// The minimiser for y in [0, L): the hull vertex whose slope interval holds y,
// refined; next to a shock, the far end of the shock is refined too.
HopfLaxSolution::Minimum HopfLaxSolution::minimum(double y) const {
  if (t_ == 0) return {y, psi0(y)};
  const std::size_t edges = hull_x_.size();
  std::size_t v = static_cast<std::size_t>(std::upper_bound(hull_x_.begin(), hull_x_.end(), y) -
                                           hull_x_.begin());  // vertex between edges v-1, v
  assert(v > 0 && v < edges);  // the three listed periods cover [0, L) with room
  v = std::clamp<std::size_t>(v, 1, edges - 1);
  Minimum best = refine(y, hull_start_[v]);
  const auto consider = [&](long node) {
    const Minimum m = refine(y, node);
    if (m.psi < best.psi) best = m;
  };
  if (hull_start_[v] - hull_start_[v - 1] >= 2) consider(hull_start_[v - 1]);
  if (hull_start_[v + 1] - hull_start_[v] >= 2) consider(hull_start_[v + 1]);
  return best;
}

// x - U t = yw + k L with yw in [0, L).
HopfLaxSolution::Frame HopfLaxSolution::moving_frame(double x) const {
  const double y = x - U_ * t_;
  Frame f{std::floor(y / L_), 0};
  f.y = y - f.k * L_;
  if (f.y >= L_) f.y -= L_, f.k += 1;
  if (f.y < 0) f.y = 0;
  return f;
}

HopfLaxSolution::Point HopfLaxSolution::locate(double x, bool with_velocity) const {
  const Frame f = moving_frame(x);
  const Minimum m = minimum(f.y);
  Point p;
  p.q = m.q + f.k * L_;
  // Lab frame: Psi(x) = Psi_w(x - U t) + U x - U^2 t / 2.
  p.psi = m.psi + U_ * x - 0.5 * U_ * U_ * t_;
  p.mass = m0(p.q);
  if (with_velocity) p.v = U_ + moving_velocity(f.y, m.q);
  return p;
}

// w = (y - q*)/t, or w0(q*) where q* solves the characteristic equation to
// rounding (the same value, without the cancellation in y - q* at small t).
double HopfLaxSolution::moving_velocity(double y, double q) const {
  if (t_ == 0) return w0(y);
  const double w = w0(q);
  const double residual = q + t_ * w - y;
  const double eps = std::numeric_limits<double>::epsilon();
  return std::abs(residual) <= 8 * eps * std::max({std::abs(y), std::abs(q), h_}) ? w : (y - q) / t_;
}

// <v> = U + (Psi_w(b - U t) - Psi_w(a - U t)) / dx: the moving-frame potential
// carries no U x term, whose rounding would grow with U.
CellAverages HopfLaxSolution::cell_averages(std::size_t cells) const {
  require(cells >= 1, "continuum.cells", cells, ">= 1");
  const double dx = L_ / static_cast<double>(cells);
  CellAverages a{std::vector<double>(cells), std::vector<double>(cells)};
  const auto edge = [&](std::size_t i) {
    const Frame f = moving_frame(static_cast<double>(i) * dx);
    const Minimum m = minimum(f.y);
    return std::pair{m.psi, m0(m.q + f.k * L_)};
  };
  auto [psi_a, mass_a] = edge(0);
  for (std::size_t i = 0; i < cells; ++i) {
    auto [psi_b, mass_b] = edge(i + 1);
    // M0(q*(x)) does not decrease (q* does not, rho0 >= 0); across a vacuum its
    // value is one, whose roundings may: kept, so rho >= 0 and the sum telescopes.
    mass_b = std::max(mass_b, mass_a);
    a.v[i] = U_ + (psi_b - psi_a) / dx;
    a.rho[i] = (mass_b - mass_a) / dx;
    psi_a = psi_b, mass_a = mass_b;
  }
  return a;
}

std::vector<Shock> HopfLaxSolution::shocks() const {
  std::vector<Shock> out;
  if (t_ == 0) return out;
  for (std::size_t c = 0; c < hull_x_.size(); ++c) {
    if (hull_start_[c + 1] - hull_start_[c] < 2 || hull_x_[c] < 0 || hull_x_[c] >= L_) continue;
    // Bitangent of g: the slope through the two tangent points, iterated.
    double xs = hull_x_[c], ql = node_q(hull_start_[c]), qr = node_q(hull_start_[c + 1]);
    for (int it = 0; it < 6; ++it) {
      bool bl = false, br = false;
      ql = root_near(xs, hull_start_[c], bl);
      qr = root_near(xs, hull_start_[c + 1], br);
      const double next = 0.5 * (ql + qr) + t_ * (psi0(qr) - psi0(ql)) / (qr - ql);
      if (next == xs) break;
      xs = next;
    }
    Shock s;
    s.x = wrap(xs + U_ * t_);
    s.mass = m0(qr) - m0(ql);
    s.jump = (ql - qr) / t_;
    s.v = U_ + (2 * xs - ql - qr) / (2 * t_);
    out.push_back(s);
  }
  std::sort(out.begin(), out.end(), [](const Shock& a, const Shock& b) { return a.x < b.x; });
  return out;
}

std::map<std::string, double> HopfLaxSolution::stats() const {
  return {{"samples", static_cast<double>(n_)},
          {"hull_clusters", static_cast<double>(period_edges_)},
          {"v0_evaluations", static_cast<double>(evaluations_)},
          {"unbracketed", static_cast<double>(unbracketed_)}};
}

std::size_t hopf_lax_samples(std::size_t cells, const HopfLaxOptions& options) {
  require(options.samples_per_cell >= 1, "hopf_lax.samples_per_cell", options.samples_per_cell, ">= 1");
  require(options.min_samples >= 16, "hopf_lax.min_samples", options.min_samples, ">= 16");
  const std::size_t n = std::max(cells * options.samples_per_cell, options.min_samples);
  const std::size_t k = options.multiple_of;
  return k > 0 ? (n + k - 1) / k * k : n;
}

}  // namespace shockgas::continuum
