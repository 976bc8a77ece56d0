// The animation's record in result.h5 and the wave's evolution in summary.json
// (frames.hpp), declared once: path, unit, meaning, and where each comes from.
#include <cmath>

#include "shockgas/app/output/layout_declarations.hpp"
#include "shockgas/continuum/registry.hpp"

namespace shockgas::app::layout {

namespace {

using Json = nlohmann::ordered_json;
using Evolution = compare::FieldEvolution;

// f(frames, out), when the run recorded frames.
template <class F>
Emit with_frames(F f) {
  return [f](const RunResults& r, Emitter& out) {
    if (r.frames) f(*r.frames, out);
  };
}

// f(frames, out), when particles ran too.
template <class F>
Emit with_clusters(F f) {
  return with_frames([f](const Frames& fr, Emitter& out) {
    if (!fr.cluster_t.empty()) f(fr, out);
  });
}

// One column of every frame's clusters, concatenated.
std::vector<double> concatenated(const Frames& f, std::vector<double> Bodies::*column) {
  std::vector<double> all;
  for (const auto& b : f.clusters) all.insert(all.end(), (b.*column).begin(), (b.*column).end());
  return all;
}

std::vector<double> counts(const Frames& f) {
  std::vector<double> n;
  for (const auto& b : f.clusters) n.push_back(static_cast<double>(b.size()));
  return n;
}

// Each solver's frames as a frames x cells matrix of `field` (v or rho).
Emit field_matrix(std::vector<double> continuum::ContinuumResult::*field) {
  return with_frames([field](const Frames& f, Emitter& out) {
    for (const auto& series : f.fields) {
      if (series.empty() || (series.front().*field).empty()) continue;
      std::vector<double> m;
      for (const auto& r : series) m.insert(m.end(), (r.*field).begin(), (r.*field).end());
      out.matrix(m, series.size(), (series.front().*field).size(), {series.front().solver});
    }
  });
}

Emit evolution_series(std::vector<double> Evolution::*series) {
  return with_frames([series](const Frames& f, Emitter& out) {
    if (!f.fields.empty()) out.values(f.evolution.*series);
  });
}

// f(evolution) -> Json, when the fields were measured and f has a finite value.
template <class F>
Emit evolution_key(F f) {
  return with_frames([f](const Frames& fr, Emitter& out) {
    if (fr.fields.empty()) return;
    const Json value = f(fr.evolution);
    if (value.is_null() || (value.is_number() && !std::isfinite(value.get<double>()))) return;
    out.json(value);
  });
}

// The frames are drawn (the animation), never measured again: float32 (storage.hpp).
Declaration drawn(Declaration d) { return stored_as(Storage::float32, std::move(d)); }

std::vector<Declaration> record() {
  const Part p = Part::animation;
  const char* particles = "when particles run";
  const char* continuum = "when continuum solvers run";
  return {
      dataset(p, "/animation/t", "time", "frame times (output.animation_frames, output.animation_spacing)",
              "", with_frames([](const Frames& f, Emitter& out) { out.values(f.t); })),
      dataset(p, "/animation/clusters/t", "time", "the frame times the particles reached (realization 0)",
              particles, with_clusters([](const Frames& f, Emitter& out) { out.values(f.cluster_t); })),
      stored_as(Storage::integer,
                dataset(p, "/animation/clusters/count", "1", "clusters in each of those frames", particles,
                        with_clusters([](const Frames& f, Emitter& out) { out.values(counts(f)); }))),
      drawn(dataset(
          p, "/animation/clusters/x", "length",
          "cluster centres of mass, frame after frame (count[k] entries per frame)", particles,
          with_clusters([](const Frames& f, Emitter& out) { out.values(concatenated(f, &Bodies::x)); }))),
      drawn(dataset(
          p, "/animation/clusters/v", "length/time", "cluster velocities (momentum / mass), as x", particles,
          with_clusters([](const Frames& f, Emitter& out) { out.values(concatenated(f, &Bodies::v)); }))),
      drawn(dataset(
          p, "/animation/clusters/m", "mass", "cluster masses, as x", particles,
          with_clusters([](const Frames& f, Emitter& out) { out.values(concatenated(f, &Bodies::m)); }))),
      drawn(dataset(p, "/animation/fields/{solver}/x", "length", "cell centres", continuum,
                    with_frames([](const Frames& f, Emitter& out) {
                      for (const auto& s : f.fields)
                        if (!s.empty()) out.values(s.front().x, {s.front().solver});
                    }))),
      drawn(dataset(p, "/animation/fields/{solver}/v", "length/time",
                    "cell averages of v at each frame (rows: frames)", continuum,
                    field_matrix(&continuum::ContinuumResult::v))),
      drawn(dataset(p, "/animation/fields/{solver}/rho", "mass/length",
                    "cell averages of rho at each frame (rows: frames)", "solvers that give a density",
                    field_matrix(&continuum::ContinuumResult::rho))),
      attribute(p, "/animation/fields@exact", "",
                "the exact solver's name (plots draw it black, dashed, as \"exact\")",
                "when the exact solver runs", with_frames([](const Frames& f, Emitter& out) {
                  for (const auto& s : f.fields)
                    if (!s.empty() && continuum::solver_info(s.front().solver).exact)
                      out.text(s.front().solver);
                })),
      attribute(p, "/animation/evolution@solver", "", "the solver whose fields the evolution measures",
                continuum, with_frames([](const Frames& f, Emitter& out) {
                  if (!f.fields.empty()) out.text(f.evolution_solver);
                })),
      dataset(p, "/animation/evolution/amplitude", "length/time", "(max v - min v) / 2 at each frame",
              continuum, evolution_series(&Evolution::amplitude)),
      dataset(p, "/animation/evolution/steepest_slope", "1/time", "least (v_{i+1} - v_i) / dx at each frame",
              continuum, evolution_series(&Evolution::steepest_slope)),
      dataset(p, "/animation/evolution/positive_area", "length^2/time",
              "int (v - <v>)^+ dx: the lobes above the mean", continuum,
              evolution_series(&Evolution::positive_area)),
      dataset(p, "/animation/evolution/negative_area", "length^2/time",
              "int (v - <v>)^- dx: the lobes below it", continuum,
              evolution_series(&Evolution::negative_area)),
      stored_as(Storage::integer, dataset(p, "/animation/evolution/shocks", "1", "shocks at each frame",
                                          continuum, evolution_series(&Evolution::shocks))),
      stored_as(
          Storage::integer,
          dataset(p, "/animation/evolution/breaking_fit", "1",
                  "1 for the smooth, resolved frames whose -1 / min dv/dx the breaking time is fitted on, "
                  "else 0",
                  continuum, evolution_series(&Evolution::formation_fit))),
      dataset(p, "/animation/evolution/amplitude_fit_t", "time",
              "the window of the amplitude's power-law fit", "with the fit",
              with_frames([](const Frames& f, Emitter& out) {
                if (const auto& a = f.evolution.amplitude_fit) out.values({a->t_min, a->t_max});
              })),
      dataset(p, "/animation/evolution/amplitude_fit", "length/time",
              "the fitted power law at the window's ends", "with the fit",
              with_frames([](const Frames& f, Emitter& out) {
                if (const auto& a = f.evolution.amplitude_fit)
                  out.values({a->prefactor * std::pow(a->t_min, a->exponent),
                              a->prefactor * std::pow(a->t_max, a->exponent)});
              })),
  };
}

std::vector<Declaration> evolution() {
  const Part p = Part::animation;
  const char* continuum = "when continuum solvers run";
  return {
      key(p, "evolution.solver", "",
          "the solver whose fields at the frame times are measured (the exact one if it runs)", continuum,
          with_frames([](const Frames& f, Emitter& out) {
            if (!f.fields.empty()) out.json(f.evolution_solver);
          })),
      key(p, "evolution.frames", "1", "frames of the animation", "",
          with_frames([](const Frames& f, Emitter& out) { out.json(f.t.size()); })),
      key(p, "evolution.first_shock_time", "time", "the first frame after t = 0 holding a shock",
          "when a shock appears", evolution_key([](const Evolution& e) { return Json(e.first_shock_time); })),
      key(p, "evolution.last_smooth_time", "time",
          "the frame before it (the breaking time lies between the two)",
          "when a shock appears after a smooth frame",
          evolution_key([](const Evolution& e) { return Json(e.last_smooth_time); })),
      with_theory(key(p, "evolution.shock_formation_time", "time",
                      "breaking time t* measured: where -1 / min dv/dx, a straight line t* - t, reaches zero",
                      "with 2 or more resolved smooth frames",
                      evolution_key([](const Evolution& e) { return Json(e.shock_formation_time); })),
                  compare::Law::breaking, "{evolution.breaking_time_theory}"),
      key(p, "evolution.shock_formation_frames", "1", "the smooth frames resolved well enough for that line",
          continuum, evolution_key([](const Evolution& e) { return Json(e.formation_frames); })),
      key(p, "evolution.breaking_time_theory", "time",
          "theory: t* = 1 / max(-v0') of the initial velocity; 0 where it jumps down (a shock from the "
          "start)",
          "for initial.velocities = \"expression\"", with_frames([](const Frames& f, Emitter& out) {
            if (std::isfinite(f.breaking_time_theory)) out.json(f.breaking_time_theory);
          })),
      with_theory(
          with_theory(
              key(p, "evolution.amplitude_exponent", "1",
                  "fitted a in (max v - min v) / 2 ~ t^a on /animation/evolution/amplitude_fit_t: after the "
                  "first shock, from the start of theory.n_wave_decay's or theory.sawtooth_decay's window, "
                  "and from t_end / compare.fit_window",
                  "where one of those laws holds, with 3 or more frames in the window",
                  evolution_key([](const Evolution& e) {
                    return e.amplitude_fit ? Json(e.amplitude_fit->exponent) : Json(nullptr);
                  })),
              compare::Law::n_wave_decay, "-1/2 (N-wave)"),
          compare::Law::sawtooth_decay, "-1 (periodic sawtooth)"),
      key(p, "evolution.amplitude_exponent_error", "1",
          "its least-squares standard error: the misfit of one deterministic run to a power law, not an "
          "error bar",
          "with the exponent", evolution_key([](const Evolution& e) {
            return e.amplitude_fit ? Json(e.amplitude_fit->exponent_error) : Json(nullptr);
          })),
      with_theory(key(p, "evolution.lobe_area_change", "1",
                      "largest |A(t) / A(0) - 1| of the lobes above and below the mean over the frames",
                      continuum, evolution_key([](const Evolution& e) { return Json(e.lobe_area_change); })),
                  compare::Law::lobe_areas, "0 (an isolated pulse without a jump)"),
      key(p, "evolution.shocks_max", "1", "most shocks in one frame", continuum,
          evolution_key([](const Evolution& e) {
            double n = 0;
            for (double s : e.shocks) n = std::max(n, s);
            return Json(n);
          })),
      key(p, "evolution.shocks_final", "1", "shocks in the last frame", continuum,
          evolution_key([](const Evolution& e) { return Json(e.shocks.back()); })),
  };
}

}  // namespace

std::vector<Declaration> frame_datasets() { return record(); }

std::vector<Declaration> frame_keys() { return evolution(); }

}  // namespace shockgas::app::layout
