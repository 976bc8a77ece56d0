#pragma once
// Error bars from the realizations for every number the particle analysis
// reports (particle_analysis.hpp): the T(t) exponent, the crossover times, the
// collapse distance and the tail exponent of the scaled velocity distribution,
// each a jackknife over realizations (jackknife.hpp) of the same analysis run on
// the ensemble mean with one realization left out.
//
// Why not the fits' own errors: the sample times of one realization are strongly
// correlated (T at 10^4 and 2 10^4 share most of their history), so a
// least-squares error that treats them as independent is several times too
// small; realizations are independent, and the jackknife over them sees every
// correlation inside one.
#include <cstddef>
#include <optional>
#include <vector>

#include "shockgas/compare/cooling_law.hpp"
#include "shockgas/compare/jackknife.hpp"
#include "shockgas/compare/particle_analysis.hpp"

namespace shockgas::compare {

// The exponent a of T = A t^a fitted (fit_power_law) to the ensemble mean of the
// rows on [t_min, t_max]. t: the sample times (as many as the longest row);
// T_rows: one row per realization (a row may be shorter: a realization that
// stopped early). Throws InputError as fit_power_law for the full ensemble.
JackknifeEstimate jackknife_T_exponent(const std::vector<double>& t,
                                       const std::vector<std::vector<double>>& T_rows, double t_min,
                                       double t_max);

// The exponent of the exact sticky gas (r = 0) from the same starts on the same
// window, and the gas's exponent less it, each a jackknife over realizations;
// the difference leaves realization i out of both at once (paired: what their
// common start gives both cancels, so its error is that of the dynamics
// alone). sticky_rows[i]: T(t) of the sticky gas from realization i's start at
// the same sample times, used as far as row i reaches (a realization that
// stopped early: the same samples of its start). Throws InputError unless there is one sticky row per
// row and 2 or more of them, or as jackknife_T_exponent.
struct PairedExponents {
  JackknifeEstimate sticky;      // the sticky gas's exponent [1]
  JackknifeEstimate difference;  // the gas's exponent less the sticky gas's [1]
};
PairedExponents jackknife_paired_T_exponents(const std::vector<double>& t,
                                             const std::vector<std::vector<double>>& T_rows,
                                             const std::vector<std::vector<double>>& sticky_rows,
                                             double t_min, double t_max);

// The crossover times (find_crossovers with the given params) of the ensemble
// mean. r: the restitution coefficient.
struct CrossoverErrors {
  JackknifeEstimate t_dissip, t_stick;  // NaN value / error where the curve shows none
};
CrossoverErrors jackknife_crossovers(const std::vector<double>& t,
                                     const std::vector<std::vector<double>>& T_rows, double r,
                                     const CrossoverParams& params = {});

// The collapse distance of the late distributions and the tail exponent a of
// analyse_velocity_distribution(h, t_min), h holding the ensemble-mean density
// of the rows. layout: zmax, bins and t of the histograms (its density is not
// read); density_rows: one histogram per realization, in ZHistogram's layout.
struct DistributionErrors {
  JackknifeEstimate collapse_distance;  // NaN if fewer than two late times
  JackknifeEstimate tail_exponent;      // NaN if the tail could not be fitted
};
DistributionErrors jackknife_distribution(const ZHistogram& layout,
                                          const std::vector<std::vector<double>>& density_rows, double t_min);

// The collapse distance of the late distributions of several ensembles taken
// together: the collapse over r and t of the paper's Fig. 4. Realization i of
// every ensemble shares its initial condition (same seed, same index), so
// realization i is left out of all of them at once. ensembles[e][i]:
// realization i of ensemble e, as in jackknife_distribution; every ensemble
// holds as many realizations. Throws InputError if there are none.
JackknifeEstimate jackknife_joint_collapse(const ZHistogram& layout,
                                           const std::vector<std::vector<std::vector<double>>>& ensembles,
                                           double t_min);

// The exponent with its jackknife error on windows of one and two decades
// [10^k, 10^(k+1)] and [10^k, 10^(k+2)] inside [t.front(), t.back()] (each with
// >= 3 samples): how the fitted exponent depends on the window.
struct WindowExponent {
  double t_min = 0, t_max = 0;  // the window [time]
  JackknifeEstimate exponent;
};
std::vector<WindowExponent> jackknife_decade_windows(const std::vector<double>& t,
                                                     const std::vector<std::vector<double>>& T_rows);

// Everything above for one ensemble, as analyse_cooling and
// analyse_velocity_distribution define it: the exponent on
// [fit_t_min, fit_t_max] (the window analyse_cooling is given) and on the decade windows, the crossovers with
// the default params, the distribution from t_min. T_rows: one series per realization at the sample times t;
// density_rows: their histograms (layout.bins = 0: none). Nothing (nullopt) for fewer than 2 realizations or
// when the ensemble's own fit is refused; a part the data cannot support is NaN, and so is the exponent
// where there is no fit window (fit_t_min >= fit_t_max: cooling_fit_scope refused one).
struct AnalysisErrors {
  JackknifeEstimate T_exponent;
  std::vector<WindowExponent> windows;
  CrossoverErrors crossovers;
  DistributionErrors distribution;
};
std::optional<AnalysisErrors> jackknife_analysis(const std::vector<double>& t,
                                                 const std::vector<std::vector<double>>& T_rows, double r,
                                                 double fit_t_min, double fit_t_max, const ZHistogram& layout,
                                                 const std::vector<std::vector<double>>& density_rows,
                                                 double t_min);

}  // namespace shockgas::compare
