#pragma once
// The far tail of the scaled velocity distribution Phi(z), z = (v - <v>) t^(1/3)
// (the paper's eq. 6: Phi ~ exp(-c |z|^3)), measured against the exact
// mass-weighted law of the clusters (cluster_velocity_law.hpp).
//
// The independent samples are clusters, not particles: every particle of a
// cluster has its velocity. So a histogram here counts both the mass and the
// clusters in each bin, and a bin is trusted only while it holds enough
// clusters. The law is symmetric, so the histogram is folded: bin b holds
// b w <= |z| < (b + 1) w and Phi_b = (mass in bin b) / (2 w total mass), a
// density of z.
//
// The tail is read two ways, each with a jackknife error over realizations
// (jackknife.hpp) and each beside the same estimator applied to the exact law's
// bin means, so that binning and the estimator's own bias cancel:
//  * the local exponent a(z) = d ln(-ln Phi) / d ln |z|: the least-squares slope
//    over 2h + 1 neighbouring bins. An exact law with asymptotic exponent 3 can
//    have a(z) well below 3 at reachable z (the mass-weighted law: 1.85 at
//    |z| = 1, 2.37 at 3.5 for D = 1/3), so a(z) is compared with the law's a(z)
//    at the same z, not with 3;
//  * the exponent of ln Phi = ln Phi0 - c |z|^a fitted on a window [z_lo, z_hi]
//    (fit_tail_exponent, velocity_distribution.hpp).
#include <cstddef>
#include <span>
#include <vector>

#include "shockgas/compare/jackknife.hpp"

namespace shockgas::compare {

// The folded histogram of one realization at one time.
class TailHistogram {
 public:
  // Bins of width `width` covering |z| < z_max. Throws InputError unless
  // 0 < width < z_max.
  TailHistogram(double width, double z_max);
  // One cluster of mass m at z (all its members at one velocity: r = 0).
  void add(double z, double m);
  // One cluster whose members have the velocities z_i and masses m_i (r > 0):
  // each member's mass goes to its bin, the cluster counts once in every bin
  // it touches. Sizes must agree.
  void add_members(std::span<const double> z, std::span<const double> m);
  // Adds another histogram binned alike (a group of realizations: the jackknife
  // may leave out groups instead of single realizations). Throws InputError if
  // the binning differs.
  TailHistogram& operator+=(const TailHistogram& other);

  double width() const { return width_; }
  std::size_t bins() const { return mass_.size(); }
  const std::vector<double>& mass() const { return mass_; }
  const std::vector<double>& clusters() const { return clusters_; }
  double total_mass() const { return total_mass_; }          // including |z| >= z_max
  double total_clusters() const { return total_clusters_; }  // including |z| >= z_max

 private:
  std::size_t bin(double z) const;  // bins() if |z| >= z_max
  double width_;
  std::vector<double> mass_, clusters_;
  double total_mass_ = 0, total_clusters_ = 0;
};

struct TailParams {
  double D = 1.0 / 3.0;         // white-noise intensity of the initial velocities, for the exact law
  double min_clusters = 25;     // a bin is in the tail while it holds at least this many (all realizations)
  std::size_t half_window = 2;  // the local exponent: slope over 2 h + 1 bins
  double z_min = 0.5;           // the local exponent from here on (ln(-ln Phi) needs Phi < 1)
};

struct TailPoint {
  double z = 0;                      // bin centre [1]
  double clusters = 0;               // clusters in the bin, all realizations
  JackknifeEstimate phi;             // Phi_b [1/z]
  double exact_phi = 0;              // the exact law's mean over the bin
  JackknifeEstimate local_exponent;  // a(z) of the data; NaN below z_min
  double exact_local_bins = 0;       // the same estimator on exact_phi
  double exact_local = 0;            // the law's own d ln(-ln Phi)/d ln z at z
};

struct TailAnalysis {
  std::vector<TailPoint> points;  // from |z| = 0 to the last bin with >= min_clusters (contiguous)
  double z_reach = 0;             // the upper edge of the last of them
  double chi_square = 0;          // sum over points with z >= z_min of ((phi - exact) / error)^2
  std::size_t dof = 0;            // those points
  double p_value = 0;             // P(chi2_dof > chi_square)
};

// realizations: one histogram per realization, or per group of realizations of
// equal size (delete-a-group jackknife), all binned alike (>= 2).
// Throws InputError if they differ in binning or there are fewer than 2.
TailAnalysis analyse_tail(const std::vector<TailHistogram>& realizations, const TailParams& params);

struct TailWindowFit {
  double z_lo = 0, z_hi = 0;  // the window; bins whose centres lie in it
  std::size_t bins = 0;
  JackknifeEstimate exponent;  // a of ln Phi = ln Phi0 - c |z|^a on the data
  double exact_exponent = 0;   // the same fit on the exact law's bin means
  JackknifeEstimate slope;     // straight-line slope of ln(-ln Phi) on ln |z| (the plot's)
  double exact_slope = 0;      // the same on the exact law's bin means
};

// Throws InputError if fewer than 4 bins of the window are in the tail
// (analyse_tail's points).
TailWindowFit fit_tail_window(const std::vector<TailHistogram>& realizations, double z_lo, double z_hi,
                              const TailParams& params);

// The exact mass-weighted law's local exponent d ln(-ln Phi)/d ln|z| at z > 0
// (intensity D), by a centred difference; Phi(z) < 1 required (else NaN).
double exact_tail_local_exponent(double z, double D);

}  // namespace shockgas::compare
