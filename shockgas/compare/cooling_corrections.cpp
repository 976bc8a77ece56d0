#include "shockgas/compare/cooling_corrections.hpp"

#include <cmath>
#include <sstream>

#include "shockgas/compare/theory.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::compare {

namespace {

std::string text(double x) { return to_text(x, 2); }

// The exponent shift of a relative excess d_min at t_min and d_max at t_max.
double shift(double d_min, double d_max, double t_min, double t_max) {
  return (std::log1p(d_max) - std::log1p(d_min)) / std::log(t_max / t_min);
}

double clusters(std::size_t N, double t) {
  return kClustersPerParticle * static_cast<double>(N) * std::pow(t, kStickyCoolingExponent);
}

}  // namespace

CoolingCorrections cooling_corrections(std::size_t N, bool lattice, double t_min, double t_max) {
  require_above("compare.fit_window", t_min, 0.0);
  require(t_max > t_min, "compare.fit_window", t_max, "t_max > t_min");
  CoolingCorrections c;
  const auto lattice_excess = [](double t) { return kLatticeExcess * std::pow(t, kStickyCoolingExponent); };
  if (lattice) c.lattice = shift(lattice_excess(t_min), lattice_excess(t_max), t_min, t_max);
  c.clusters_end = clusters(N, t_max);
  c.finite_size =
      shift(-kFiniteSizeDeficit / clusters(N, t_min), -kFiniteSizeDeficit / c.clusters_end, t_min, t_max);
  c.expected = kStickyCoolingExponent + c.lattice + c.finite_size;
  return c;
}

double student_t_95(std::size_t dof) {
  require(dof >= 1, "student_t.dof", dof, ">= 1");
  static constexpr double kTable[] = {12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228,
                                      2.201,  2.179, 2.160, 2.145, 2.131, 2.120, 2.110, 2.101, 2.093, 2.086,
                                      2.080,  2.074, 2.069, 2.064, 2.060, 2.056, 2.052, 2.048, 2.045, 2.042};
  constexpr std::size_t kRows = sizeof kTable / sizeof kTable[0];
  if (dof <= kRows) return kTable[dof - 1];
  return 1.960 + 2.4 / static_cast<double>(dof);  // 2.021 at 40, 2.000 at 60, 1.980 at 120 (within 0.001)
}

namespace {

bool usable(const JackknifeEstimate& e) {
  return std::isfinite(e.value) && std::isfinite(e.error) && e.error > 0;
}

std::string with_error(const JackknifeEstimate& e, int digits) {
  return to_text(e.value, digits) + (usable(e) ? " +- " + to_text(e.error, 2) : " (no jackknife error)");
}

// The sticky gas of the same starts, and the gas against it.
void same_starts_text(std::ostream& out, const PairedExponents& p) {
  out << " The exact sticky gas from the same starts (the hull at r = 0, realization by realization) gives a "
         "= "
      << with_error(p.sticky, 4) << " on this window; the gas less it: " << with_error(p.difference, 2)
      << " (jackknife of the pairs).";
}

// What the rest of a departure beyond the corrections is, from the gas and the
// sticky gas of its starts; false (nothing said) where their errors cannot weigh it.
bool same_starts_cause(std::ostream& out, const PairedExponents& p, const CoolingCorrections& c,
                       std::size_t realizations) {
  if (!usable(p.difference) || !usable(p.sticky)) return false;
  const double apart = std::abs(p.difference.value) / p.difference.error;
  if (apart > 2)
    out << "is the gas's own: it departs from the sticky gas of its starts by "
        << to_text(p.difference.value, 2) << ", " << to_text(apart, 2)
        << " paired errors: the window may still hold its approach to the sticky gas.";
  else if (std::abs(p.sticky.value - c.expected) > 2 * p.sticky.error)
    out << "is these starts' own: the exact sticky gas from them departs as much, so it is the spread of the "
           "exponent from one start to another at this size, which an error from "
        << realizations << " realizations, of " << realizations - 1
        << " degree(s) of freedom, estimates only roughly.";
  else
    out << "is within the errors of the pairs: the gas is within 2 paired errors of the sticky gas of its "
           "starts, and that within 2 of its own errors of the corrected value.";
  return true;
}

}  // namespace

std::string cooling_departure_text(double a, double sigma, std::size_t realizations,
                                   const CoolingCorrections& c, double t_min, double t_max,
                                   const std::optional<PairedExponents>& same_starts) {
  std::ostringstream out;
  out << "Corrections expected on [" << text(t_min) << ", " << text(t_max)
      << "], measured with the exact hull (docs/paper/fig1.md): finite size (about "
      << std::lround(c.clusters_end) << " clusters per realization at t = " << text(t_max) << ") "
      << to_text(c.finite_size, 2) << ", lattice start " << to_text(c.lattice, 2)
      << ": a = " << to_text(c.expected, 4) << " expected.";
  if (same_starts) same_starts_text(out, *same_starts);
  if (!std::isfinite(sigma) || sigma <= 0) {
    out << " Without an error estimate the departure from -2/3 (" << to_text(a - kStickyCoolingExponent, 2)
        << ") cannot be weighed.";
    return out.str();
  }
  const double sigmas = std::abs(a - kStickyCoolingExponent) / sigma;
  const double from_expected = std::abs(a - c.expected) / sigma;
  out << " The departure from -2/3 is " << to_text(sigmas, 2) << " sigma";
  if (sigmas <= 2) {
    out << ": within the statistical error.";
    return out.str();
  }
  out << ", beyond 2 sigma: ";
  if (from_expected <= 2)
    out << "the corrections account for it (a is " << to_text(from_expected, 2)
        << " sigma from the corrected value).";
  else {
    const double t95 = student_t_95(realizations - 1);
    out << "the corrections account for " << to_text(c.expected - kStickyCoolingExponent, 2)
        << " of it; the rest (" << to_text(a - c.expected, 2) << ", " << to_text(from_expected, 2)
        << " sigma) ";
    if (same_starts && same_starts_cause(out, *same_starts, c, realizations)) return out.str();
    if (from_expected <= t95)
      out << "is within the statistics of " << realizations << " realizations: their error has "
          << realizations - 1 << " degree(s) of freedom, and 95 % of Student's t lies within "
          << to_text(t95, 3) << " sigma.";
    else
      out << "is beyond the statistics of " << realizations << " realizations (95 % within "
          << to_text(t95, 3)
          << " sigma) and the measured corrections: the window may still hold a crossover.";
  }
  return out.str();
}

}  // namespace shockgas::compare
