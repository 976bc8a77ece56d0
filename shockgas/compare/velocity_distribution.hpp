#pragma once
// The scaled velocity distribution (the paper's Fig. 4): in the sticky regime
// P(v, t) = t^(1/3) Phi(v t^(1/3)), the same Phi at every late time and for
// every r, with tail Phi(z) ~ exp(-c |z|^3).
//
// A distribution here is a histogram of z = v t^(1/3) normalised as a density
// of z: density_j = (weight in bin j) / (total weight * width_j), so that it
// integrates to the fraction of the weight inside the binned range.
#include <cstddef>
#include <span>
#include <vector>

namespace shockgas::compare {

struct ScaledDistribution {
  double t = 0;                 // time of the sample [time]
  std::vector<double> z_edges;  // bin edges in z = v t^(1/3), increasing (bins + 1 values)
  std::vector<double> density;  // density of z in each bin [1/z]
};

// Histogram of samples v_i with weights w_i (empty = all 1; for r = 0 clusters,
// the cluster masses) on `bins` equal bins of z in [-z_max, z_max]. Samples
// outside the range count in the total weight but in no bin.
// Throws InputError unless t > 0, z_max > 0, bins >= 1, sizes agree, w >= 0,
// and the total weight is > 0.
ScaledDistribution scaled_histogram(std::span<const double> v, std::span<const double> w, double t,
                                    double z_max, std::size_t bins);

// A histogram already binned in z (e.g. by the particle engine), or in v with
// v_edges (then z edges = v edges * t^(1/3)), turned into a density of z.
// counts: weight per bin (bins = edges - 1), normalised by their sum.
ScaledDistribution normalise_z_histogram(std::span<const double> z_edges, std::span<const double> counts,
                                         double t);
ScaledDistribution rescale_v_histogram(std::span<const double> v_edges, std::span<const double> counts,
                                       double t);

// The mean of distributions binned alike (same z edges; e.g. several late
// times or realizations, to steady a tail fit): density averaged bin by bin, t
// the last one's. Throws InputError if d is empty or the edges differ.
ScaledDistribution mean_distribution(const std::vector<ScaledDistribution>& d);

// The standard deviation of z under d's density (each bin's weight at its centre).
double standard_deviation(const ScaledDistribution& d);

// How well distributions collapse: the mean, over all pairs, of the L1 distance
//   D_ab = int |Phi_a(z) - Phi_b(z)| dz
// on the z range common to all of them, evaluated at `grid_points` midpoints of
// that range (each density piecewise constant in its bins). 0 = perfect
// collapse; 2 = disjoint supports. Throws InputError unless there are >= 2
// distributions with overlapping ranges and grid_points >= 1.
double collapse_distance(const std::vector<ScaledDistribution>& d, std::size_t grid_points = 400);

// Tail exponent: ln Phi(z) = ln Phi0 - c |z|^a fitted to the points with
// |z| >= z_min and Phi > 0. For fixed a this is linear in (ln Phi0, c)
// (least squares, Eigen); a minimises the residual sum of squares RSS(a), found
// by a scan of [a_min, a_max] refined by golden-section search. This needs no
// separate estimate of Phi0 (whose bin at z = 0 is itself an average).
// exponent_error = sqrt(2 sigma^2 / RSS''(a)), sigma^2 = RSS / (n - 3): the
// curvature (profile least squares) estimate; NaN when n <= 3 or the residual is 0.
struct TailFit {
  double exponent = 0;        // a; theory 3 [1]
  double exponent_error = 0;  // [1]
  double c = 0;               // [1/z^a]
  double phi0 = 0;            // Phi0 [1/z]
  double rms_residual = 0;    // of ln Phi [1]
  std::size_t points = 0;     // points used
  bool at_bound = false;      // the best a is at a_min or a_max: the tail does not
                              // determine it (too few or too noisy points); error NaN
};
// Throws InputError if sizes differ, z_min < 0, the range is empty or fewer than 3 points qualify.
TailFit fit_tail_exponent(std::span<const double> z, std::span<const double> phi, double z_min,
                          double a_min = 0.5, double a_max = 8.0);
// The same on a distribution's bin centres and densities.
TailFit fit_tail_exponent(const ScaledDistribution& d, double z_min, double a_min = 0.5, double a_max = 8.0);

}  // namespace shockgas::compare
