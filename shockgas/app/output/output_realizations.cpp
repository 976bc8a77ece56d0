// Each realization's own series in result.h5, and the error bars they give the
// analysis (a jackknife over realizations, shockgas/compare/realization_errors.hpp) in
// summary.json, declared once.
#include <cmath>
#include <limits>

#include "shockgas/app/output/layout_declarations.hpp"

namespace shockgas::app::layout {

namespace {

using Json = nlohmann::ordered_json;

// Rows of different lengths as one matrix, NaN where a row ends early.
void ragged_matrix(const std::vector<std::vector<double>>& rows, Emitter& out) {
  std::size_t cols = 0;
  for (const auto& row : rows) cols = std::max(cols, row.size());
  if (rows.empty() || cols == 0) return;
  std::vector<double> m(rows.size() * cols, std::numeric_limits<double>::quiet_NaN());
  for (std::size_t i = 0; i < rows.size(); ++i)
    std::copy(rows[i].begin(), rows[i].end(), m.begin() + i * cols);
  out.matrix(m, rows.size(), cols);
}

// f(errors) -> JackknifeEstimate, emitted as its error (null when not finite).
template <class F>
Emit error_of(F f) {
  return [f](const RunResults& r, Emitter& out) {
    if (!r.particles || !r.particles->errors) return;
    const double e = f(*r.particles->errors).error;
    out.json(std::isfinite(e) ? Json(e) : Json(nullptr));
  };
}

}  // namespace

std::vector<Declaration> realization_datasets() {
  const Part p = Part::particles;
  auto ensemble = [](auto f) {
    return [f](const RunResults& r, Emitter& out) {
      if (r.particles) f(r.particles->ensemble, out);
    };
  };
  return {
      dataset(p, "/particles/realizations/T", "length^2/time^2",
              "T at the sample times, one row per realization (NaN after an early stop)", "",
              ensemble([](const particles::EnsembleResult& e, Emitter& out) {
                ragged_matrix(e.T_by_realization, out);
              })),
      dataset(p, "/particles/realizations/histogram_density", "time^(2/3)/length",
              "each realization's histogram density, rows: realizations, columns: times x bins",
              "when particles.histogram_bins > 0",
              ensemble([](const particles::EnsembleResult& e, Emitter& out) {
                ragged_matrix(e.histogram_by_realization, out);
              })),
  };
}

std::vector<Declaration> realization_error_keys() {
  const Part p = Part::analysis;
  using E = compare::AnalysisErrors;
  const std::string when = "with 2 or more realizations";
  return {
      key(p, "analysis.jackknife_realizations", "1", "realizations the errors below leave out one at a time",
          when,
          [](const RunResults& r, Emitter& out) {
            if (r.particles && r.particles->errors) out.json(r.particles->errors->T_exponent.samples);
          }),
      key(p, "analysis.T_exponent_jackknife_error", "1",
          "error of analysis.T_exponent from the realizations (jackknife); the least-squares error "
          "treats correlated sample times as independent",
          "with analysis.T_exponent and 2 or more realizations",
          [](const RunResults& r, Emitter& out) {  // not of a fit the summary does not carry
            if (r.particles && r.particles->cooling.fit)
              error_of([](const E& e) { return e.T_exponent; })(r, out);
          }),
      key(p, "analysis.T_exponent_windows", "1",
          "the T exponent fitted on every window of one and two decades, each {t_min, t_max, exponent, "
          "jackknife_error}",
          when,
          [](const RunResults& r, Emitter& out) {
            if (!r.particles || !r.particles->errors) return;
            Json list = Json::array();
            for (const compare::WindowExponent& w : r.particles->errors->windows)
              list.push_back({{"t_min", w.t_min},
                              {"t_max", w.t_max},
                              {"exponent", w.exponent.value},
                              {"jackknife_error",
                               std::isfinite(w.exponent.error) ? Json(w.exponent.error) : Json(nullptr)}});
            out.json(list);
          }),
      key(p, "analysis.t_dissip_error", "time", "jackknife error of analysis.t_dissip (null: not crossed)",
          when, error_of([](const E& e) { return e.crossovers.t_dissip; })),
      key(p, "analysis.t_stick_error", "time", "jackknife error of analysis.t_stick (null: not crossed)",
          when, error_of([](const E& e) { return e.crossovers.t_stick; })),
      key(p, "analysis.velocity_collapse_distance_error", "1",
          "jackknife error of analysis.velocity_collapse_distance", when + " and a histogram",
          error_of([](const E& e) { return e.distribution.collapse_distance; })),
      key(p, "analysis.velocity_tail_exponent_jackknife_error", "1",
          "jackknife error of analysis.velocity_tail_exponent", when + " and a histogram",
          error_of([](const E& e) { return e.distribution.tail_exponent; })),
  };
}

}  // namespace shockgas::app::layout
