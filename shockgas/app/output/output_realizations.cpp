// Each realization's own series in result.h5, and the error bars they give the
// analysis (a jackknife over realizations, shockgas/compare/realization_errors.hpp) in
// summary.json, declared once.
#include <algorithm>
#include <cmath>
#include <limits>

#include "shockgas/app/output/layout_declarations.hpp"
#include "shockgas/compare/sticky_same_starts.hpp"
#include "shockgas/particles/params.hpp"

namespace shockgas::app::layout {

namespace {

using Json = nlohmann::ordered_json;

std::string clusters_when() {
  return "when particles.final_clusters records them (auto: " + particles::final_clusters_auto_rule() + ")";
}

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

// f(same starts) -> JackknifeEstimate, emitted as its value or its error (null when not finite).
template <class F>
Emit same_starts(F f, bool error) {
  return [f, error](const RunResults& r, Emitter& out) {
    if (!r.particles || !r.particles->same_starts) return;
    const compare::JackknifeEstimate e = f(*r.particles->same_starts);
    const double x = error ? e.error : e.value;
    out.json(std::isfinite(x) ? Json(x) : Json(nullptr));
  };
}

// Every realization's final clusters, one field of them (&Bodies::x, v or m)
// concatenated in index order; nothing unless every realization recorded them.
bool all_recorded(const particles::EnsembleResult& e) {
  return !e.final_clusters.empty() && std::all_of(e.final_clusters.begin(), e.final_clusters.end(),
                                                  [](const auto& c) { return c.has_value(); });
}
void concatenated(const particles::EnsembleResult& e, std::vector<double> Bodies::*field, Emitter& out) {
  if (!all_recorded(e)) return;
  std::vector<double> all;
  for (const auto& c : e.final_clusters) all.insert(all.end(), ((*c).*field).begin(), ((*c).*field).end());
  out.values(all);
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
      dataset(p, "/particles/realizations/stop_time", "time",
              "when each realization ended (t_end where it completed; /particles@stop_reason for "
              "realization 0)",
              "", ensemble([](const particles::EnsembleResult& e, Emitter& out) {
                std::vector<double> t;
                for (const particles::RunStop& s : e.stops) t.push_back(s.time);
                out.values(t);
              })),
      stored_as(Storage::integer,
                dataset(p, "/particles/realizations/clusters_count", "1",
                        "how many clusters of at least two particles each realization holds at its end: "
                        "realization k's are entries sum(count[:k]) .. of clusters_x, clusters_v, clusters_m",
                        clusters_when(), ensemble([](const particles::EnsembleResult& e, Emitter& out) {
                          if (!all_recorded(e)) return;
                          std::vector<double> count;
                          for (const auto& c : e.final_clusters)
                            count.push_back(static_cast<double>(c->size()));
                          out.values(count);
                        }))),
      dataset(p, "/particles/realizations/clusters_x", "length",
              "centre of mass of each cluster of at least two particles (as /particles/n_clusters counts "
              "them, at the end; r = 0: the merged bodies), each realization's in order of x",
              clusters_when(), ensemble([](const particles::EnsembleResult& e, Emitter& out) {
                concatenated(e, &Bodies::x, out);
              })),
      dataset(p, "/particles/realizations/clusters_v", "length/time", "velocity of each of those clusters",
              clusters_when(), ensemble([](const particles::EnsembleResult& e, Emitter& out) {
                concatenated(e, &Bodies::v, out);
              })),
      dataset(p, "/particles/realizations/clusters_m", "mass", "mass of each of those clusters",
              clusters_when(), ensemble([](const particles::EnsembleResult& e, Emitter& out) {
                concatenated(e, &Bodies::m, out);
              })),
  };
}

std::vector<Declaration> realization_error_keys() {
  const Part p = Part::analysis;
  using E = compare::AnalysisErrors;
  using P = compare::PairedExponents;
  const std::string when = "with 2 or more realizations";
  const std::string same_starts_when =
      "with analysis.T_exponent, particles.r > 0, 2 or more realizations and N x "
      "realizations <= " +
      to_text(compare::kSameStartsBodies);
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
      key(p, "analysis.T_exponent_sticky", "1",
          "the T exponent of the exact sticky gas (the hull at r = 0) from the same starts, realization by "
          "realization, on the window of analysis.T_exponent (shockgas/compare/sticky_same_starts.hpp)",
          same_starts_when, same_starts([](const P& s) { return s.sticky; }, false)),
      key(p, "analysis.T_exponent_sticky_error", "1", "jackknife error of analysis.T_exponent_sticky",
          same_starts_when, same_starts([](const P& s) { return s.sticky; }, true)),
      key(p, "analysis.T_exponent_minus_sticky", "1",
          "analysis.T_exponent less analysis.T_exponent_sticky: the gas against the sticky gas of its own "
          "starts",
          same_starts_when, same_starts([](const P& s) { return s.difference; }, false)),
      key(p, "analysis.T_exponent_minus_sticky_error", "1",
          "jackknife error of analysis.T_exponent_minus_sticky, each realization left out of both (paired)",
          same_starts_when, same_starts([](const P& s) { return s.difference; }, true)),
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
