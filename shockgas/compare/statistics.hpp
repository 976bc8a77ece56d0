#pragma once
// Small statistics shared by the comparison fits: quantiles and the weighted
// least-squares straight line (Eigen), with standard errors.
#include <cstddef>
#include <span>
#include <vector>

namespace shockgas::compare {

// The p-quantile (0 <= p <= 1) of values, by linear interpolation between
// order statistics (Hyndman & Fan 1996, type 7: the default of R and NumPy).
// Throws InputError if values is empty or p is outside [0, 1].
double quantile(std::vector<double> values, double p);

// Median, lower and upper quartile of a sample (type-7 quantiles).
struct Quartiles {
  double q25 = 0;     // lower quartile
  double median = 0;  // median
  double q75 = 0;     // upper quartile
};
Quartiles quartiles(const std::vector<double>& values);

// y ~ intercept + slope * x by weighted least squares,
//   minimise sum_i w_i (y_i - intercept - slope x_i)^2,
// solved by a column-pivoting Householder QR of the sqrt(w)-scaled design
// matrix (Eigen). Standard errors from the covariance sigma^2 (A^T W A)^-1 with
// sigma^2 = weighted RSS / (n - 2) (n = points with w > 0); 0 when n = 2.
struct LineFit {
  double slope = 0;
  double intercept = 0;
  double slope_error = 0;      // standard error of the slope
  double intercept_error = 0;  // standard error of the intercept
  double rms_residual = 0;     // sqrt(weighted RSS / sum w)
  std::size_t points = 0;      // points with w > 0
};

// weights empty = all 1. Throws InputError if sizes differ, a weight is
// negative, fewer than 2 points have w > 0 or the x of those are all equal.
LineFit fit_line(std::span<const double> x, std::span<const double> y, std::span<const double> weights = {});

}  // namespace shockgas::compare
