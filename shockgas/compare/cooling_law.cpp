#include "shockgas/compare/cooling_law.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>

#include "shockgas/compare/statistics.hpp"
#include "shockgas/compare/theory.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::compare {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

void validate_series(const std::vector<double>& t, const std::vector<double>& T) {
  require(t.size() == T.size(), "compare.T", T.size(),
          "one value per time (" + std::to_string(t.size()) + ")");
  require(t.size() >= 2, "compare.t", t.size(), "at least 2 samples");
  for (std::size_t i = 0; i < t.size(); ++i) {
    require(std::isfinite(t[i]) && t[i] > 0, "compare.t", t[i], "finite, > 0");
    require(std::isfinite(T[i]) && T[i] > 0, "compare.T", T[i], "finite, > 0");
    if (i > 0) require(t[i] > t[i - 1], "compare.t", t[i], "increasing");
  }
}

std::vector<double> logs(const std::vector<double>& a) {
  std::vector<double> out(a.size());
  std::transform(a.begin(), a.end(), out.begin(), [](double x) { return std::log(x); });
  return out;
}

std::vector<double> centered_differences(const std::vector<double>& lt, const std::vector<double>& lT) {
  const std::size_t n = lt.size();
  std::vector<double> alpha(n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t a = i == 0 ? 0 : i - 1, b = i + 1 == n ? n - 1 : i + 1;
    alpha[i] = (lT[b] - lT[a]) / (lt[b] - lt[a]);
  }
  return alpha;
}

std::vector<double> windowed_slopes(const std::vector<double>& lt, const std::vector<double>& lT,
                                    double half) {
  const double half_ln = half * std::log(10.0);
  const std::size_t n = lt.size();
  std::vector<double> alpha(n);
  const std::vector<double> neighbours = centered_differences(lt, lT);
  std::size_t lo = 0, hi = 0;
  for (std::size_t i = 0; i < n; ++i) {
    while (lt[i] - lt[lo] > half_ln) ++lo;
    while (hi + 1 < n && lt[hi + 1] - lt[i] <= half_ln) ++hi;
    if (hi - lo + 1 < 2) {  // window too narrow: fall back to the neighbours
      alpha[i] = neighbours[i];
      continue;
    }
    const std::span<const double> x(lt.data() + lo, hi - lo + 1), y(lT.data() + lo, hi - lo + 1);
    alpha[i] = fit_line(x, y).slope;
  }
  return alpha;
}

// ln t where alpha crosses `level` between samples i and i + 1 (linear in ln t).
double crossing_time(const std::vector<double>& lt, const std::vector<double>& alpha, std::size_t i,
                     double level) {
  const double f = (level - alpha[i]) / (alpha[i + 1] - alpha[i]);
  return std::exp(lt[i] + f * (lt[i + 1] - lt[i]));
}

}  // namespace

std::vector<double> local_exponents(const std::vector<double>& t, const std::vector<double>& T,
                                    double half_window_decades) {
  validate_series(t, T);
  require(std::isfinite(half_window_decades) && half_window_decades >= 0, "compare.half_window_decades",
          half_window_decades, ">= 0");
  const auto lt = logs(t), lT = logs(T);
  return half_window_decades > 0 ? windowed_slopes(lt, lT, half_window_decades)
                                 : centered_differences(lt, lT);
}

PowerLawFit fit_power_law(const std::vector<double>& t, const std::vector<double>& T, double t_min,
                          double t_max) {
  validate_series(t, T);
  std::vector<double> x, y;
  for (std::size_t i = 0; i < t.size(); ++i)
    if (t[i] >= t_min && t[i] <= t_max) {
      x.push_back(std::log(t[i]));
      y.push_back(std::log(T[i]));
    }
  require(x.size() >= 2, "compare.fit_window", t_min, "a window [t_min, t_max] holding at least 2 samples");
  const LineFit line = fit_line(x, y);
  return PowerLawFit{line.slope, line.slope_error, std::exp(line.intercept), x.size(), t_min, t_max};
}

Crossovers find_crossovers(const std::vector<double>& t, const std::vector<double>& T, double r,
                           const CrossoverParams& params) {
  const std::vector<double> alpha = local_exponents(t, T, params.half_window_decades);
  const auto lt = logs(t);
  Crossovers c;
  c.t_dissip_theory = dissipation_time(r);
  c.t_stick_theory = sticking_time(r);
  c.t_dissip = c.t_stick = kNaN;
  const std::size_t i_min =
      static_cast<std::size_t>(std::min_element(alpha.begin(), alpha.end()) - alpha.begin());
  c.min_exponent = alpha[i_min];
  c.t_min_exponent = t[i_min];
  c.separated = c.min_exponent <= params.stick_level;
  if (!c.separated) return c;
  for (std::size_t i = i_min; i-- > 0;)
    if (alpha[i] >= params.dissip_level && alpha[i + 1] < params.dissip_level) {
      c.t_dissip = crossing_time(lt, alpha, i, params.dissip_level);
      break;
    }
  for (std::size_t i = i_min; i + 1 < alpha.size(); ++i)
    if (alpha[i] <= params.stick_level && alpha[i + 1] > params.stick_level) {
      c.t_stick = crossing_time(lt, alpha, i, params.stick_level);
      break;
    }
  return c;
}

}  // namespace shockgas::compare
