#include "shockgas/compare/velocity_tail.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "shockgas/compare/cluster_velocity_law.hpp"
#include "shockgas/compare/goodness_of_fit.hpp"
#include "shockgas/compare/statistics.hpp"
#include "shockgas/compare/velocity_distribution.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::compare {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Phi_b of the realizations without leave_out (== their number: all), from the summed rows.
class FoldedDensity {
 public:
  explicit FoldedDensity(const std::vector<TailHistogram>& h) : width_(h.front().width()), mass_(masses(h)) {
    for (const TailHistogram& x : h) total_.push_back(x.total_mass()), all_ += x.total_mass();
  }
  std::size_t realizations() const { return mass_.rows(); }
  std::vector<double> phi(std::size_t leave_out) const {
    std::vector<double> p = mass_.sum(leave_out);
    const double total = leave_out < total_.size() ? all_ - total_[leave_out] : all_;
    for (double& x : p) x /= 2 * width_ * total;
    return p;
  }

 private:
  static std::vector<std::vector<double>> masses(const std::vector<TailHistogram>& h) {
    std::vector<std::vector<double>> r;
    for (const TailHistogram& x : h) r.push_back(x.mass());
    return r;
  }
  double width_;
  LeaveOneOutMeans mass_;
  std::vector<double> total_;
  double all_ = 0;
};

double centre(double width, std::size_t b) { return (static_cast<double>(b) + 0.5) * width; }

// d ln(-ln phi) / d ln z at bins [first, last] (inclusive): the least-squares
// slope over the bins within h of each, cut at first and last; NaN where one
// of them has phi outside (0, 1).
std::vector<double> local_slopes(const std::vector<double>& phi, double width, std::size_t first,
                                 std::size_t last, std::size_t h) {
  std::vector<double> slope;
  for (std::size_t b = first; b <= last; ++b) {
    std::vector<double> x, y;
    for (std::size_t k = std::max(first, b >= h ? b - h : 0); k <= std::min(last, b + h); ++k) {
      x.push_back(std::log(centre(width, k)));
      y.push_back(phi[k] > 0 && phi[k] < 1 ? std::log(-std::log(phi[k])) : kNaN);
    }
    const bool finite = std::all_of(y.begin(), y.end(), [](double v) { return std::isfinite(v); });
    slope.push_back(finite && x.size() >= 2 ? fit_line(x, y).slope : kNaN);
  }
  return slope;
}

void require_alike(const std::vector<TailHistogram>& h) {
  require(h.size() >= 2, "tail.realizations", h.size(), "at least 2 realizations");
  for (const TailHistogram& x : h)
    require(x.width() == h.front().width() && x.bins() == h.front().bins(), "tail.bins", x.bins(),
            "every realization binned alike");
}

std::vector<double> exact_bins(double width, std::size_t bins, double D) {
  std::vector<double> edges(bins + 1);
  for (std::size_t b = 0; b <= bins; ++b) edges[b] = static_cast<double>(b) * width;
  return cluster_law_on_bins(edges, D);
}

// The tail's bins: from 0 to the last of the contiguous bins with >= min_clusters.
std::size_t tail_bins(const std::vector<TailHistogram>& h, double min_clusters) {
  std::size_t n = 0;
  for (; n < h.front().bins(); ++n) {
    double c = 0;
    for (const TailHistogram& x : h) c += x.clusters()[n];
    if (c < min_clusters) break;
  }
  return n;
}

std::size_t first_bin_from(double z_min, double width) {
  return static_cast<std::size_t>(std::max(0.0, std::ceil(z_min / width - 0.5)));
}

}  // namespace

TailHistogram::TailHistogram(double width, double z_max) : width_(width) {
  require(width > 0 && z_max > width && std::isfinite(z_max), "tail.bin_width", width, "0 < width < z_max");
  const auto n = static_cast<std::size_t>(std::ceil(z_max / width - 1e-9));
  mass_.assign(n, 0.0);
  clusters_.assign(n, 0.0);
}

std::size_t TailHistogram::bin(double z) const {
  const double b = std::floor(std::abs(z) / width_);
  return b < static_cast<double>(mass_.size()) ? static_cast<std::size_t>(b) : mass_.size();
}

void TailHistogram::add(double z, double m) {
  total_mass_ += m;
  total_clusters_ += 1;
  const std::size_t b = bin(z);
  if (b < mass_.size()) mass_[b] += m, clusters_[b] += 1;
}

void TailHistogram::add_members(std::span<const double> z, std::span<const double> m) {
  require(z.size() == m.size(), "tail.members", m.size(), "one mass per velocity");
  total_clusters_ += 1;
  std::size_t last = mass_.size();
  std::vector<std::size_t> touched;
  for (std::size_t i = 0; i < z.size(); ++i) {
    total_mass_ += m[i];
    const std::size_t b = bin(z[i]);
    if (b == mass_.size()) continue;
    mass_[b] += m[i];
    if (b != last && std::find(touched.begin(), touched.end(), b) == touched.end()) touched.push_back(b);
    last = b;
  }
  for (const std::size_t b : touched) clusters_[b] += 1;
}

TailHistogram& TailHistogram::operator+=(const TailHistogram& other) {
  require(other.width_ == width_ && other.bins() == bins(), "tail.bins", other.bins(),
          "histograms binned alike");
  for (std::size_t b = 0; b < bins(); ++b) mass_[b] += other.mass_[b], clusters_[b] += other.clusters_[b];
  total_mass_ += other.total_mass_, total_clusters_ += other.total_clusters_;
  return *this;
}

TailAnalysis analyse_tail(const std::vector<TailHistogram>& h, const TailParams& p) {
  require_alike(h);
  const double w = h.front().width();
  const FoldedDensity density(h);
  const std::size_t n = tail_bins(h, p.min_clusters), R = density.realizations();
  const std::vector<double> exact = exact_bins(w, h.front().bins(), p.D);
  TailAnalysis a;
  if (n == 0) return a;
  a.z_reach = static_cast<double>(n) * w;
  const std::vector<JackknifeEstimate> phi =
      jackknife_components(R, [&](std::size_t i) { return density.phi(i); });
  const std::size_t first = std::min(first_bin_from(p.z_min, w), n - 1);
  const std::vector<JackknifeEstimate> local = jackknife_components(
      R, [&](std::size_t i) { return local_slopes(density.phi(i), w, first, n - 1, p.half_window); });
  const std::vector<double> exact_local = local_slopes(exact, w, first, n - 1, p.half_window);
  for (std::size_t b = 0; b < n; ++b) {
    TailPoint q;
    q.z = centre(w, b);
    for (const TailHistogram& x : h) q.clusters += x.clusters()[b];
    q.phi = phi[b];
    q.exact_phi = exact[b];
    q.local_exponent.value = q.local_exponent.error = q.exact_local_bins = q.exact_local = kNaN;
    if (b >= first) {
      q.local_exponent = local[b - first];
      q.exact_local_bins = exact_local[b - first];
      q.exact_local = exact_tail_local_exponent(q.z, p.D);
      const double pull = (q.phi.value - q.exact_phi) / q.phi.error;
      if (std::isfinite(pull)) a.chi_square += pull * pull, ++a.dof;
    }
    a.points.push_back(q);
  }
  a.p_value = a.dof > 0 ? chi_square_survival(a.chi_square, a.dof) : kNaN;
  return a;
}

TailWindowFit fit_tail_window(const std::vector<TailHistogram>& h, double z_lo, double z_hi,
                              const TailParams& p) {
  require_alike(h);
  const double w = h.front().width();
  const std::size_t n = tail_bins(h, p.min_clusters);
  std::vector<std::size_t> in;
  for (std::size_t b = 0; b < n; ++b)
    if (centre(w, b) >= z_lo && centre(w, b) <= z_hi) in.push_back(b);
  require(in.size() >= 4, "tail.window", z_hi,
          "a window holding >= 4 tail bins (each >= min_clusters clusters)");
  const FoldedDensity density(h);
  const std::vector<double> exact = exact_bins(w, h.front().bins(), p.D);
  // Both estimators on the window's bins of a density.
  auto fits = [&](const std::vector<double>& phi) {
    std::vector<double> z, f, lz, llf;
    for (const std::size_t b : in) {
      z.push_back(centre(w, b)), f.push_back(phi[b]);
      lz.push_back(std::log(centre(w, b))), llf.push_back(std::log(-std::log(phi[b])));
    }
    const TailFit tail = fit_tail_exponent(z, f, 0.0);
    return std::vector<double>{tail.at_bound ? kNaN : tail.exponent, fit_line(lz, llf).slope};
  };
  TailWindowFit fit;
  fit.z_lo = z_lo, fit.z_hi = z_hi, fit.bins = in.size();
  const std::vector<JackknifeEstimate> e =
      jackknife_components(density.realizations(), [&](std::size_t i) { return fits(density.phi(i)); });
  fit.exponent = e[0], fit.slope = e[1];
  const std::vector<double> x = fits(exact);
  fit.exact_exponent = x[0], fit.exact_slope = x[1];
  return fit;
}

double exact_tail_local_exponent(double z, double D) {
  const double h = 1e-3;
  auto y = [&](double lz) {
    const double phi = cluster_velocity_density(std::exp(lz), D);
    return phi > 0 && phi < 1 ? std::log(-std::log(phi)) : kNaN;
  };
  const double lz = std::log(std::abs(z));
  return (y(lz + h) - y(lz - h)) / (2 * h);
}

}  // namespace shockgas::compare
