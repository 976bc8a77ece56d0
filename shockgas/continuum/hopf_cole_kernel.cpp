// Hopf-Cole in the log domain: ln theta by log-sum-exp of the heat kernel,
// centred on the Hopf-Lax minimiser, over the window where the exponent is within
// kWindow of its maximum. See hopf_cole.hpp.
//
// With G_y(q) = Psi0(q) + (y - q)^2 / 2t the exponent is -G_y(q) / 2 nu, so
//     ln theta(y) = -G_y(q*) / 2 nu + ln sum_q exp(-(G_y(q) - G_y(q*)) / 2 nu) + ln(dq / sqrt(4 pi nu t)).
// G_y(q) = F(q) - (y/t) q + y^2/2t with F(q) = Psi0(q) + q^2 / 2t, so the minimiser
// q* is the vertex of the lower convex hull of F touched by the line of slope y/t,
// and every q with G_y(q) - G_y(q*) <= 2 nu kWindow lies where the hull itself is
// within 2 nu kWindow of that line: an interval found by walking the hull.
// Both the touching vertex and the interval move right as y grows.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "shockgas/continuum/hopf_cole.hpp"

namespace shockgas::continuum {

namespace {

constexpr double kWindow = 40.0;  // e^-40 = 4e-18: terms below this never change a double

// Unrolled quadrature nodes q_m = (m0 + m) dq with Psi0 interpolated linearly
// between the cell edges (Psi0 of piecewise-constant v0), periodically.
struct Nodes {
  double dq = 0;
  long m0 = 0;
  std::vector<double> q, psi;
};

Nodes unrolled_nodes(const MovingFramePotential& p, std::size_t refine, double lo, double hi) {
  const long n = static_cast<long>(p.psi.size());
  const long r = static_cast<long>(refine);
  Nodes nodes;
  nodes.dq = p.spacing() / static_cast<double>(refine);
  nodes.m0 = static_cast<long>(std::floor(lo / nodes.dq)) - 1;
  const long m1 = static_cast<long>(std::ceil(hi / nodes.dq)) + 1;
  nodes.q.reserve(static_cast<std::size_t>(m1 - nodes.m0 + 1));
  nodes.psi.reserve(nodes.q.capacity());
  for (long m = nodes.m0; m <= m1; ++m) {
    const long cell = (m >= 0 ? m / r : -((-m + r - 1) / r));  // floor(m / r)
    const long sub = m - cell * r;
    const long j = ((cell % n) + n) % n;
    const double w = static_cast<double>(sub) / static_cast<double>(r);
    nodes.q.push_back(static_cast<double>(m) * nodes.dq);
    nodes.psi.push_back((1 - w) * p.psi[static_cast<std::size_t>(j)] +
                        w * p.psi[static_cast<std::size_t>((j + 1) % n)]);
  }
  return nodes;
}

// Indices of the lower convex hull of (q_m, F_m) (Andrew's monotone chain), q ascending.
std::vector<std::size_t> lower_hull(const std::vector<double>& q, const std::vector<double>& F) {
  std::vector<std::size_t> h;
  for (std::size_t m = 0; m < q.size(); ++m) {
    while (h.size() >= 2) {
      const std::size_t a = h[h.size() - 2], b = h.back();
      // drop b if it lies on or above the chord a -> m
      if ((F[b] - F[a]) * (q[m] - q[a]) >= (F[m] - F[a]) * (q[b] - q[a]))
        h.pop_back();
      else
        break;
    }
    h.push_back(m);
  }
  return h;
}

class KernelSum {
 public:
  KernelSum(const Nodes& nodes, double nu, double t) : nodes_(nodes), nu_(nu), t_(t) {
    std::vector<double> F(nodes.q.size());
    for (std::size_t m = 0; m < F.size(); ++m) F[m] = nodes.psi[m] + nodes.q[m] * nodes.q[m] / (2 * t);
    hull_ = lower_hull(nodes.q, F);
    F_ = std::move(F);
  }

  // ln theta(y) without the constant ln(dq / sqrt(4 pi nu t)); y must not decrease between calls.
  double operator()(double y) {
    const double slope = y / t_;
    while (vertex_ + 1 < hull_.size() && edge_slope(vertex_) < slope) ++vertex_;
    const std::size_t star = hull_[vertex_];
    const double g_star = G(star, y);
    const double cut = 2 * nu_ * kWindow;
    const double lo = window_end(y, g_star, cut, -1), hi = window_end(y, g_star, cut, +1);
    // Node range of [lo, hi]; it always holds the minimiser (rounding cannot drop it).
    const double from = std::max(0.0, std::ceil((lo - nodes_.q[0]) / nodes_.dq));
    const double to = std::floor((hi - nodes_.q[0]) / nodes_.dq);
    const std::size_t first = std::min(static_cast<std::size_t>(from), star);
    const std::size_t last =
        std::clamp(static_cast<std::size_t>(std::max(to, 0.0)), star, nodes_.q.size() - 1);
    double sum = 0;
    for (std::size_t m = first; m <= last; ++m) sum += std::exp(-(G(m, y) - g_star) / (2 * nu_));
    return -g_star / (2 * nu_) + std::log(sum);
  }

 private:
  double G(std::size_t m, double y) const {
    const double d = y - nodes_.q[m];
    return nodes_.psi[m] + d * d / (2 * t_);
  }
  double edge_slope(std::size_t k) const {
    const std::size_t a = hull_[k], b = hull_[k + 1];
    return (F_[b] - F_[a]) / (nodes_.q[b] - nodes_.q[a]);
  }
  // Walks the hull from the touching vertex in direction dir (+1 right, -1 left) to
  // where hull - line first exceeds cut (linear along an edge) and returns that q.
  double window_end(double y, double g_star, double cut, int dir) const {
    std::size_t k = vertex_;
    double d_inside = 0;
    while (true) {
      if ((dir < 0 && k == 0) || (dir > 0 && k + 1 == hull_.size())) return nodes_.q[hull_[k]];
      const std::size_t next = dir > 0 ? k + 1 : k - 1;
      const double d_next = G(hull_[next], y) - g_star;
      if (d_next > cut) {
        const double qa = nodes_.q[hull_[k]], qb = nodes_.q[hull_[next]];
        return qa + (qb - qa) * (cut - d_inside) / (d_next - d_inside);
      }
      k = next;
      d_inside = d_next;
    }
  }

  const Nodes& nodes_;
  double nu_, t_;
  std::vector<double> F_;
  std::vector<std::size_t> hull_;
  std::size_t vertex_ = 0;
};

// Quadrature nodes per cell: the trapezoid sum of a Gaussian of width
// sigma = sqrt(2 nu t) has relative error ~ 2 exp(-2 pi^2 sigma^2 / dq^2), so
// dq <= sigma / 2 makes it < 1e-30.
std::size_t kernel_refinement(double h, double nu, double t) {
  const double sigma = std::sqrt(2 * nu * t);
  return static_cast<std::size_t>(std::clamp(std::ceil(2 * h / sigma), 1.0, 1024.0));
}

}  // namespace

double log_theta_kernel_terms(const MovingFramePotential& psi0, double nu, double t) {
  const double dq = psi0.spacing() / static_cast<double>(kernel_refinement(psi0.spacing(), nu, t));
  const double window = 2 * std::sqrt(2 * t * 2 * nu * kWindow);  // hull curvature 1/t
  return static_cast<double>(psi0.psi.size()) * (window / dq + 1);
}

LogTheta log_theta_kernel(const MovingFramePotential& psi0, double nu, double t, double shift) {
  const std::size_t n = psi0.psi.size();
  const double h = psi0.spacing(), L = psi0.length;
  const std::size_t refine = kernel_refinement(h, nu, t);
  // Evaluation points y_j = j h - s, s = shift mod L in [0, L). A contributing q has
  // (y - q)^2 / 2t <= Psi0(y) - min Psi0 + 2 nu kWindow, hence |y - q| <= reach.
  const double s = shift - L * std::floor(shift / L);
  const double reach = std::sqrt(2 * t * (psi0.spread() + 2 * nu * kWindow));
  const Nodes nodes = unrolled_nodes(psi0, refine, -s - reach, L - s + reach);
  KernelSum kernel(nodes, nu, t);
  const double constant = std::log(nodes.dq / std::sqrt(4 * std::numbers::pi * nu * t));

  LogTheta out;
  out.nodes_per_cell = refine;
  out.values.resize(n);
  for (std::size_t j = 0; j < n; ++j) out.values[j] = kernel(static_cast<double>(j) * h - s) + constant;
  return out;
}

}  // namespace shockgas::continuum
