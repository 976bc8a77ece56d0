#pragma once
// The cooling law T(t) of the inelastic gas (docs/design.md §1, eq. 3 of the paper):
// T ~ 1 for t << t_dissip = 1/eps, T ~ eps^-2 t^-2 up to t_stick = eps^(-3/2),
// then T ~ t^(-2/3) (eps = (1 - r) / 2).
//
// Local exponent alpha(t) = d ln T / d ln t: plateaus 0, -2 and -2/3 in the
// three regimes.
//
// Crossover times read off the curve. The asymptotes 1 and (eps t)^-2 meet at
// t_dissip, (eps t)^-2 and t^(-2/3) at t_stick; a smooth crossover between two
// power laws passes the mean of their exponents near where they meet (exactly,
// for T = A t^a + B t^b, at the meeting point). So:
//   t_dissip = the last time before the minimum of alpha that alpha falls
//              through dissip_level (default -1, between 0 and -2);
//   t_stick  = the first time after the minimum of alpha that alpha rises
//              through stick_level (default -4/3, between -2 and -2/3).
// Both need evidence of the cooling regime: the regimes count as separated only
// if min alpha <= stick_level (alpha went clearly below the sticky plateau -2/3);
// otherwise both are NaN. A noisy sticky plateau (single realization, few
// clusters) then reports no crossover instead of a spurious one; so do r = 0 and
// r = 0.5, where eps^(-3/2) / eps^(-1) = eps^(-1/2) <= 2 leaves no cooling
// plateau. Crossings are interpolated linearly in ln t between samples; either
// is also NaN if the series starts or ends inside the regime it would leave.
#include <cstddef>
#include <vector>

namespace shockgas::compare {

// alpha_i = d ln T / d ln t at t_i: centered differences in (ln t, ln T)
// (one-sided at the ends) when half_window_decades = 0; otherwise the
// least-squares slope of ln T against ln t over the samples with
// |log10 t_j - log10 t_i| <= half_window_decades (smooths a noisy series).
// Throws InputError unless t is increasing and > 0, T > 0, sizes agree and >= 2.
std::vector<double> local_exponents(const std::vector<double>& t, const std::vector<double>& T,
                                    double half_window_decades = 0);

// T = prefactor * t^exponent fitted by least squares of ln T on ln t over the
// samples with t_min <= t <= t_max (Eigen); exponent_error is the standard error.
struct PowerLawFit {
  double exponent = 0;          // [1]
  double exponent_error = 0;    // [1]
  double prefactor = 0;         // [T unit / time^exponent]
  std::size_t points = 0;       // samples in the window
  double t_min = 0, t_max = 0;  // the window [time]
};
// Throws InputError as local_exponents, or if fewer than 2 samples are in the window.
PowerLawFit fit_power_law(const std::vector<double>& t, const std::vector<double>& T, double t_min,
                          double t_max);

struct CrossoverParams {
  double dissip_level = -1.0;        // alpha level marking t_dissip [1]
  double stick_level = -4.0 / 3.0;   // alpha level marking t_stick [1]
  double half_window_decades = 0.0;  // smoothing of alpha, as in local_exponents [decades];
                                     // ~ 0.1-0.2 for a single noisy realization
};

struct Crossovers {
  double t_dissip = 0;         // measured, NaN if not crossed [time]
  double t_stick = 0;          // measured, NaN if not crossed [time]
  double t_dissip_theory = 0;  // 1 / eps [time]
  double t_stick_theory = 0;   // eps^(-3/2) [time]
  double min_exponent = 0;     // the minimum of alpha [1]
  double t_min_exponent = 0;   // where it is reached [time]
  bool separated = false;      // min alpha <= stick_level: the cooling regime is visible
};
// r: the restitution coefficient (for the theory values).
Crossovers find_crossovers(const std::vector<double>& t, const std::vector<double>& T, double r,
                           const CrossoverParams& params = {});

}  // namespace shockgas::compare
