#include "shockgas/compare/realization_errors.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "shockgas/compare/velocity_distribution.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::compare {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The sample times a mean of `size` columns reaches.
std::vector<double> first(const std::vector<double>& t, std::size_t size) {
  return {t.begin(), t.begin() + static_cast<std::ptrdiff_t>(std::min(size, t.size()))};
}

// The late distributions of analyse_velocity_distribution for a mean density.
std::vector<ScaledDistribution> late_distributions(const ZHistogram& layout, std::vector<double> density,
                                                   double t_min) {
  ZHistogram h = layout;
  h.density = std::move(density);
  return analyse_velocity_distribution(h, t_min).late;
}

// The exponent fitted to the mean of the rows but leave_out (all: leave_out =
// rows()); NaN where too few samples are left in the window.
double exponent_without(const std::vector<double>& t, const LeaveOneOutMeans& T, std::size_t leave_out,
                        double t_min, double t_max) {
  const std::vector<double> mean = T.mean(leave_out);
  try {
    return fit_power_law(first(t, mean.size()), mean, t_min, t_max).exponent;
  } catch (const InputError&) {
    return kNaN;  // too few samples left in the window without realization leave_out
  }
}

// The exponent's jackknife over the rows of T; InputError where the mean of
// them all cannot be fitted.
JackknifeEstimate exponent_jackknife(const std::vector<double>& t, const LeaveOneOutMeans& T, double t_min,
                                     double t_max) {
  fit_power_law(first(t, T.mean(T.rows()).size()), T.mean(T.rows()), t_min, t_max);  // refuses bad input
  return jackknife(T.rows(), [&](std::size_t i) { return exponent_without(t, T, i, t_min, t_max); });
}

}  // namespace

JackknifeEstimate jackknife_T_exponent(const std::vector<double>& t,
                                       const std::vector<std::vector<double>>& T_rows, double t_min,
                                       double t_max) {
  return exponent_jackknife(t, LeaveOneOutMeans(T_rows), t_min, t_max);
}

PairedExponents jackknife_paired_T_exponents(const std::vector<double>& t,
                                             const std::vector<std::vector<double>>& T_rows,
                                             const std::vector<std::vector<double>>& sticky_rows,
                                             double t_min, double t_max) {
  require(sticky_rows.size() == T_rows.size(), "jackknife.sticky_rows", sticky_rows.size(),
          "one per realization (" + std::to_string(T_rows.size()) + ")");
  // A realization that stopped early has a shorter row: its sticky twin is cut
  // at the same sample, so that both means average the same starts at every time.
  std::vector<std::vector<double>> twins = sticky_rows;
  for (std::size_t i = 0; i < twins.size(); ++i)
    if (twins[i].size() > T_rows[i].size()) twins[i].resize(T_rows[i].size());
  const LeaveOneOutMeans gas(T_rows), sticky(std::move(twins));
  PairedExponents p;
  p.sticky = exponent_jackknife(t, sticky, t_min, t_max);
  p.difference = jackknife(gas.rows(), [&](std::size_t i) {
    return exponent_without(t, gas, i, t_min, t_max) - exponent_without(t, sticky, i, t_min, t_max);
  });
  return p;
}

std::vector<WindowExponent> jackknife_decade_windows(const std::vector<double>& t,
                                                     const std::vector<std::vector<double>>& T_rows) {
  std::vector<WindowExponent> out;
  if (t.empty() || !(t.front() > 0)) return out;
  for (const double decades : {1.0, 2.0})
    for (double k = std::ceil(std::log10(t.front()) - 1e-9); k + decades <= std::log10(t.back()) + 1e-9;
         k += 1) {
      const double lo = std::pow(10.0, k), hi = std::pow(10.0, k + decades);
      const auto in = std::count_if(t.begin(), t.end(), [&](double x) { return x >= lo && x <= hi; });
      if (in >= 3) out.push_back({lo, hi, jackknife_T_exponent(t, T_rows, lo, hi)});
    }
  return out;
}

CrossoverErrors jackknife_crossovers(const std::vector<double>& t,
                                     const std::vector<std::vector<double>>& T_rows, double r,
                                     const CrossoverParams& params) {
  const LeaveOneOutMeans T(T_rows);
  auto crossovers = [&](std::size_t i) {
    const std::vector<double> mean = T.mean(i);
    return find_crossovers(first(t, mean.size()), mean, r, params);
  };
  CrossoverErrors e;
  e.t_dissip = jackknife(T.rows(), [&](std::size_t i) { return crossovers(i).t_dissip; });
  e.t_stick = jackknife(T.rows(), [&](std::size_t i) { return crossovers(i).t_stick; });
  return e;
}

DistributionErrors jackknife_distribution(const ZHistogram& layout,
                                          const std::vector<std::vector<double>>& density_rows,
                                          double t_min) {
  const LeaveOneOutMeans density(density_rows);
  auto analysis = [&](std::size_t i) {
    ZHistogram h = layout;
    h.density = density.mean(i);
    return analyse_velocity_distribution(h, t_min);
  };
  const std::vector<JackknifeEstimate> e = jackknife_components(density.rows(), [&](std::size_t i) {
    const DistributionAnalysis a = analysis(i);
    const bool tail = a.not_determined.empty() && a.tail.points > 0 && !a.tail.at_bound;
    return std::vector<double>{a.collapse_distance ? *a.collapse_distance : kNaN,
                               tail ? a.tail.exponent : kNaN};
  });
  return DistributionErrors{e[0], e[1]};
}

JackknifeEstimate jackknife_joint_collapse(const ZHistogram& layout,
                                           const std::vector<std::vector<std::vector<double>>>& ensembles,
                                           double t_min) {
  require(!ensembles.empty(), "jackknife.ensembles", ensembles.size(), "at least one ensemble");
  std::vector<LeaveOneOutMeans> densities;
  for (const auto& rows : ensembles) {
    densities.emplace_back(rows);
    require(densities.back().rows() == densities.front().rows(), "jackknife.realizations",
            densities.back().rows(), "as many realizations in every ensemble");
  }
  return jackknife(densities.front().rows(), [&](std::size_t i) {
    std::vector<ScaledDistribution> all;
    for (const LeaveOneOutMeans& d : densities)
      for (ScaledDistribution& s : late_distributions(layout, d.mean(i), t_min)) all.push_back(std::move(s));
    return all.size() >= 2 ? collapse_distance(all) : kNaN;
  });
}

std::optional<AnalysisErrors> jackknife_analysis(const std::vector<double>& t,
                                                 const std::vector<std::vector<double>>& T_rows, double r,
                                                 double fit_t_min, double fit_t_max, const ZHistogram& layout,
                                                 const std::vector<std::vector<double>>& density_rows,
                                                 double t_min) {
  if (T_rows.size() < 2) return std::nullopt;
  AnalysisErrors e;
  e.T_exponent = {kNaN, kNaN, kNaN, T_rows.size(), 0};  // no window (fit_t_min >= fit_t_max): no exponent
  try {
    if (fit_t_min < fit_t_max) e.T_exponent = jackknife_T_exponent(t, T_rows, fit_t_min, fit_t_max);
    e.windows = jackknife_decade_windows(t, T_rows);
    e.crossovers = jackknife_crossovers(t, T_rows, r);
  } catch (const InputError&) {
    return std::nullopt;  // the ensemble's own analysis says why (analyse_cooling)
  }
  const JackknifeEstimate none{kNaN, kNaN, kNaN, density_rows.size(), 0};
  e.distribution = {none, none};
  if (layout.bins > 0 && density_rows.size() == T_rows.size()) {
    try {
      e.distribution = jackknife_distribution(layout, density_rows, t_min);
    } catch (const InputError&) {
      // the distribution's own analysis says why (analyse_velocity_distribution)
    }
  }
  return e;
}

}  // namespace shockgas::compare
