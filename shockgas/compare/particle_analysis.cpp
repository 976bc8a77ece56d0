#include "shockgas/compare/particle_analysis.hpp"

#include "shockgas/core/error.hpp"

namespace shockgas::compare {

CoolingAnalysis analyse_cooling(const std::vector<double>& t, const std::vector<double>& T, double r,
                                double t_min, double t_max, const std::string& no_window) {
  CoolingAnalysis a;
  if (t.size() < 3) return a;  // nothing to read off
  std::size_t in_window = 0;
  for (double ti : t) in_window += ti >= t_min && ti <= t_max;
  try {
    a.local_exponent = local_exponents(t, T);
    a.crossovers = find_crossovers(t, T, r);
    if (!no_window.empty())
      a.not_determined = "no fit window: " + no_window;
    else if (in_window < 3)
      a.not_determined =
          "fewer than 3 samples in the fit window [" + to_text(t_min, 3) + ", " + to_text(t_max, 3) + "]";
    else
      a.fit = fit_power_law(t, T, t_min, t_max);
  } catch (const InputError& e) {
    a.fit.reset();
    a.not_determined = e.what();
  }
  return a;
}

double ZHistogram::centre(std::size_t b) const {
  return -zmax + (static_cast<double>(b) + 0.5) * 2 * zmax / static_cast<double>(bins);
}

std::vector<double> ZHistogram::centres() const {
  std::vector<double> z(bins);
  for (std::size_t b = 0; b < bins; ++b) z[b] = centre(b);
  return z;
}

double ZHistogram::width() const { return centre(1) - centre(0); }

// Equal to -zmax + b (2 zmax / bins) up to rounding; formed from the centres so
// that the figures of merit stay those of earlier versions to the last bit.
std::vector<double> ZHistogram::edges() const {
  std::vector<double> e(bins + 1);
  for (std::size_t b = 0; b <= bins; ++b) e[b] = centre(0) - 0.5 * width() + static_cast<double>(b) * width();
  return e;
}

DistributionAnalysis analyse_velocity_distribution(const ZHistogram& h, double t_min) {
  DistributionAnalysis a;
  const std::size_t bins = h.bins;
  if (bins < 4 || h.t.empty()) return a;
  const std::vector<double> edges = h.edges();
  try {
    for (std::size_t k = h.t.size() / 2; k < h.t.size(); ++k) {
      if (h.t[k] < t_min) continue;
      std::vector<double> counts(bins);
      for (std::size_t b = 0; b < bins; ++b) counts[b] = h.density[k * bins + b] * h.width();
      a.late.push_back(normalise_z_histogram(edges, counts, h.t[k]));
    }
    if (a.late.size() < 2) return a;
    a.collapse_distance = collapse_distance(a.late);
    // The tail is fitted on the mean of the collapsed distributions (steadier than
    // one time), beyond one standard deviation of z.
    const ScaledDistribution mean = mean_distribution(a.late);
    a.tail_z_min = standard_deviation(mean);
    a.tail = fit_tail_exponent(mean, a.tail_z_min);
  } catch (const InputError& e) {
    a.not_determined = e.what();
  }
  return a;
}

}  // namespace shockgas::compare
