#pragma once
// Error bars from independent realizations: the delete-one jackknife
// (Quenouille 1956, Tukey 1958; Efron & Tibshirani, An Introduction to the
// Bootstrap, 1993, ch. 11).
//
// An estimate theta = F(realizations) (a fitted exponent of the ensemble-mean
// T(t), a crossover time, a distance between histograms) is recomputed with each
// realization i left out, theta_(i); with theta_(.) their mean,
//
//     error = sqrt((n - 1) / n * sum_i (theta_(i) - theta_(.))^2),
//     bias  = (n - 1) (theta_(.) - theta).
//
// For the mean of i.i.d. samples the error is exactly s / sqrt(n). Unlike the
// least-squares error of a fit through correlated sample times, it sees every
// correlation inside one realization, because realizations are what is
// independent. It needs n >= 2 and an F smooth in the data (it fails for the
// median and other non-smooth statistics).
#include <cstddef>
#include <functional>
#include <vector>

namespace shockgas::compare {

struct JackknifeEstimate {
  double value = 0;         // theta on all realizations
  double error = 0;         // jackknife standard error; NaN if a leave-one-out estimate is not finite
  double bias = 0;          // (n - 1)(theta_(.) - theta); value - bias is the bias-corrected estimate
  std::size_t samples = 0;  // n, the realizations
  std::size_t failed = 0;   // leave-one-out estimates that were not finite
};

// estimate(leave_out): theta without realization leave_out (0 <= leave_out < n),
// or on all of them when leave_out == n. Throws InputError unless n >= 2.
JackknifeEstimate jackknife(std::size_t n, const std::function<double(std::size_t leave_out)>& estimate);

// The same for an estimate with several components (a curve): component j of
// the result is the jackknife of component j. All calls must return the same
// number of components (else InputError).
std::vector<JackknifeEstimate> jackknife_components(
    std::size_t n, const std::function<std::vector<double>(std::size_t leave_out)>& estimate);

// Means over realizations of rows that may differ in length (a realization that
// stopped early has fewer samples): column k averages the rows that reach k.
// mean(leave_out) leaves row leave_out out (leave_out == rows(): none), in
// O(columns) from column sums, so a jackknife over n rows costs O(n columns).
class LeaveOneOutMeans {
 public:
  // Throws InputError if there are fewer than 2 rows.
  explicit LeaveOneOutMeans(std::vector<std::vector<double>> rows);
  std::size_t rows() const { return rows_.size(); }
  // The columns reached by at least one row other than leave_out; a column no
  // remaining row reaches is dropped (so the result may be shorter).
  std::vector<double> mean(std::size_t leave_out) const;
  // Sums over rows leaving one out, for estimates that are ratios of sums.
  std::vector<double> sum(std::size_t leave_out) const;

 private:
  std::vector<std::vector<double>> rows_;
  std::vector<double> sum_, count_;
};

}  // namespace shockgas::compare
