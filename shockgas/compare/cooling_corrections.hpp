#pragma once
// Why a fitted cooling exponent departs from -2/3: the corrections to the
// sticky gas's T ~ t^(-2/3) measured with the exact hull at 10^8-10^9
// particles (docs/paper/fig1.md, "why the exponent drifts with the fit window"):
//
//   lattice start   dT/T = +0.06 t^(-2/3)  (T t^(2/3) = 0.21547, 0.21337,
//                   0.21298 at t = 10, 110, 1151 against the continuum's 0.21285)
//   finite size     dT/T = -2.75 / n_c, n_c = 1.9 N t^(-2/3) clusters per
//                   realization (measured -(2.5 to 3) / n_c: -3.0 % at n_c = 88,
//                   -1.9 % at 190, -0.55 % at 400)
//
// A relative excess d(t) shifts the exponent fitted on [t_min, t_max] by
// about (ln(1 + d(t_max)) - ln(1 + d(t_min))) / ln(t_max / t_min).
#include <cstddef>
#include <optional>
#include <string>

#include "shockgas/compare/realization_errors.hpp"

namespace shockgas::compare {

inline constexpr double kLatticeExcess = 0.06;       // dT/T = +0.06 t^(-2/3) [1]
inline constexpr double kFiniteSizeDeficit = 2.75;   // dT/T = -2.75 / n_c [1]
inline constexpr double kClustersPerParticle = 1.9;  // n_c = 1.9 N t^(-2/3) [1]

struct CoolingCorrections {
  double lattice = 0;       // exponent shift from a lattice start (0 for random positions) [1]
  double finite_size = 0;   // exponent shift from n_c clusters per realization [1]
  double clusters_end = 0;  // n_c at t_max [1]
  double expected = 0;      // -2/3 + lattice + finite_size [1]
};

// N: particles per realization; lattice: whether they start on a lattice.
// Needs 0 < t_min < t_max (else InputError).
CoolingCorrections cooling_corrections(std::size_t N, bool lattice, double t_min, double t_max);

// The words of report.md for an exponent a with jackknife error sigma over
// `realizations` (sigma NaN: none) on [t_min, t_max]: the corrections, and a
// departure from -2/3 beyond 2 sigma flagged with the part of it they account
// for and, for the rest, its measured cause. With same_starts (the exact sticky
// gas from the same starts, jackknife_paired_T_exponents) and finite, positive
// errors of both: the gas's dynamics where it lies more than 2 paired errors
// from the sticky gas of its starts; else the starts' own where that sticky gas
// lies more than 2 of its errors from the corrected value; else within the
// pairs' errors. Otherwise: whether the statistics of so few realizations
// account for it: an error from n realizations has n - 1 degrees
// of freedom, and 95 % of Student's t lies within student_t_95(n - 1) of it
// (12.7 sigma for one).
std::string cooling_departure_text(double a, double sigma, std::size_t realizations,
                                   const CoolingCorrections& c, double t_min, double t_max,
                                   const std::optional<PairedExponents>& same_starts = std::nullopt);

// The two-sided 95 % quantile of Student's t with `dof` degrees of freedom
// (tables of Abramowitz & Stegun 26.7; 1.96 as dof -> infinity). dof >= 1.
double student_t_95(std::size_t dof);

}  // namespace shockgas::compare
