#pragma once
// What the particles alone show (docs/design.md §2, rung 4): the
// cooling law T(t) ~ t^a with its crossovers, and the collapse and tail of the
// scaled velocity distribution, from an ensemble's sample-time series. An
// analysis the data cannot support is skipped (too few samples) or "not
// determined" with the reason (a refused input, such as an empty tail).
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "shockgas/compare/cooling_law.hpp"
#include "shockgas/compare/velocity_distribution.hpp"

namespace shockgas::compare {

struct CoolingAnalysis {
  std::optional<PowerLawFit> fit;      // T = A t^a on [t_min, t_max], if >= 3 samples there
  std::vector<double> local_exponent;  // d ln T / d ln t at the sample times
  Crossovers crossovers;               // t_dissip, t_stick read off the curve, and their theory
  std::string not_determined;          // why the data could not be analysed; empty if they could
};

// t, T: the sample times and the (ensemble-mean) temperature; r: restitution
// (for the crossover theory); the fit window [t_min, t_max] is
// cooling_fit_scope's (theory_scope.hpp). With `no_window` (why that scope
// has none) nothing is fitted and not_determined says why; the local exponents
// and the crossovers are read off the curve either way.
CoolingAnalysis analyse_cooling(const std::vector<double>& t, const std::vector<double>& T, double r,
                                double t_min, double t_max, const std::string& no_window = {});

// A histogram of z = (v - <v>) t^(1/3) on `bins` equal bins of [-zmax, zmax] at
// each sample time: density[k * bins + b] (particles::ScaledHistogram's layout).
struct ZHistogram {
  double zmax = 0;
  std::size_t bins = 0;
  std::vector<double> t;
  std::vector<double> density;
  double centre(std::size_t b) const;  // -zmax + (b + 1/2) (2 zmax / bins)
  std::vector<double> centres() const;
  double width() const;               // the spacing of the centres
  std::vector<double> edges() const;  // bins + 1 edges: centre(0) - width / 2 + b width
};

struct DistributionAnalysis {
  std::vector<ScaledDistribution> late;  // the distributions compared: late half of the samples, t >= t_min
  std::optional<double> collapse_distance;  // their mean L1 distance, if there are two or more
  double tail_z_min = 0;                    // the tail fit's start: one standard deviation of z
  TailFit tail;                             // Phi ~ exp(-c |z|^a) on the mean distribution, |z| >= tail_z_min
  std::string not_determined;               // why not, if an input was refused; empty otherwise
};

// Needs >= 4 bins and >= 2 late sample times with t >= t_min; otherwise `late` holds what there was.
DistributionAnalysis analyse_velocity_distribution(const ZHistogram& h, double t_min);

}  // namespace shockgas::compare
