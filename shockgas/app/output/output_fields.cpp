// The datasets and attributes of result.h5 from the analysis, the continuum, the
// comparison and a sweep, declared once: path, unit, meaning, and where each
// comes from.
#include <cmath>

#include "shockgas/app/output/layout_declarations.hpp"
#include "shockgas/compare/theory.hpp"
#include "shockgas/continuum/registry.hpp"

namespace shockgas::app::layout {

namespace {

template <class T, class F>
std::vector<double> column(const std::vector<T>& items, F&& f) {
  std::vector<double> out;
  out.reserve(items.size());
  for (const auto& item : items) out.push_back(f(item));
  return out;
}

std::vector<Declaration> analysis() {
  const Part p = Part::analysis;
  auto fitted = [](auto f) {
    return [f](const RunResults& r, Emitter& out) {
      if (r.particles && r.particles->cooling.fit) f(r.particles->cooling, *r.particles->cooling.fit, out);
    };
  };
  auto theory = [](double value) {
    return [value](const RunResults& r, Emitter& out) {
      if (r.particles) out.number(value);
    };
  };
  auto exact = [](auto f) {
    return [f](const RunResults& r, Emitter& out) {
      if (r.particles && r.particles->exact) f(*r.particles->exact, out);
    };
  };
  const char* white_noise = "when the start is white noise on a lattice";
  return {
      dataset(p, "/particles/analysis/T_fit_t", "time", "window of the late-time power-law fit", "",
              fitted([](const auto&, const compare::PowerLawFit& f, Emitter& out) {
                out.values({f.t_min, f.t_max});
              })),
      dataset(p, "/particles/analysis/T_fit_T", "length^2/time^2", "the fitted power law at the window ends",
              "", fitted([](const auto&, const compare::PowerLawFit& f, Emitter& out) {
                out.values({f.prefactor * std::pow(f.t_min, f.exponent),
                            f.prefactor * std::pow(f.t_max, f.exponent)});
              })),
      dataset(p, "/particles/analysis/T_local_exponent", "1", "d ln T / d ln t at /particles/t", "",
              [](const RunResults& r, Emitter& out) {  // fitted or not (no window across a crossover)
                if (r.particles && !r.particles->cooling.local_exponent.empty())
                  out.values(r.particles->cooling.local_exponent);
              }),
      attribute(
          p, "/particles/analysis@T_exponent", "1", "the fitted exponent of T(t)", "",
          fitted([](const auto&, const compare::PowerLawFit& f, Emitter& out) { out.number(f.exponent); })),
      attribute(p, "/particles/analysis@T_exponent_theory", "1",
                "theory: T ~ t^(-2/3) in the sticky-gas regime", "", theory(compare::kStickyCoolingExponent)),
      attribute(p, "/particles/analysis@T_cooling_exponent_theory", "1",
                "theory: T ~ t^-2 in homogeneous cooling", "", theory(compare::kHomogeneousCoolingExponent)),
      attribute(
          p, "/particles/analysis@T_amplitude_exact", "length^2/time^(4/3)",
          "exact T t^(2/3) of the sticky gas (r = 0) from this white noise, the late-time law of every r "
          "(shockgas/compare/white_noise_references.hpp)",
          white_noise, exact([](const compare::WhiteNoiseReferences& w, Emitter& out) {
            out.number(w.temperature_amplitude);
          })),
      dataset(p, "/particles/analysis/n_clusters_exact", "1",
              "the exact expected number of shocks heavier than (k - 1/2) M / N (k = "
              "particles.min_cluster_particles, "
              "2 by default) of Burgers turbulence from this white noise at each /particles/t "
              "(shockgas/compare/shock_mass_law.hpp): what /particles/n_clusters "
              "approaches once the gas is sticky and the shocks span many particles",
              "when the start is white noise on a lattice and particles.clusters",
              [](const RunResults& r, Emitter& out) {
                if (r.particles && !r.particles->n_clusters_exact.empty())
                  out.values(r.particles->n_clusters_exact);
              }),
      attribute(p, "/particles/analysis@n_shocks_exact_coefficient", "time^(2/3)",
                "C of the exact number of shocks C t^(-2/3) of Burgers turbulence from this white noise, the "
                "small ones included (shockgas/compare/white_noise_references.hpp)",
                white_noise, exact([](const compare::WhiteNoiseReferences& w, Emitter& out) {
                  out.number(w.shock_count_coefficient);
                })),
  };
}

std::vector<Declaration> continuum() {
  const Part p = Part::continuum;
  // f(result, out) for each solver's result.
  auto each = [](auto f) {
    return [f](const RunResults& r, Emitter& out) {
      for (const auto& c : r.continuum) f(c.result, out);
    };
  };
  // The same for the fields, stored only when output.fields.
  auto each_field = [](auto f) {
    return [f](const RunResults& r, Emitter& out) {
      if (!r.scene->output.fields) return;
      for (const auto& c : r.continuum) f(c.result, out);
    };
  };
  auto with_shocks = [](auto f) {
    return [f](const continuum::ContinuumResult& c, Emitter& out) {
      if (c.has_shocks) out.values(column(c.shocks, f), {c.solver});
    };
  };
  auto info = [](const continuum::ContinuumResult& c) { return continuum::solver_info(c.solver); };
  const char* fields = "when output.fields";
  const char* shocks = "solvers that know their shocks";
  using Result = continuum::ContinuumResult;
  return {
      dataset(p, "/continuum/{solver}/x", "length", "cell centres", fields,
              each_field([](const Result& c, Emitter& out) { out.values(c.x, {c.solver}); })),
      dataset(p, "/continuum/{solver}/v", "length/time", "cell averages of the velocity at t", fields,
              each_field([](const Result& c, Emitter& out) { out.values(c.v, {c.solver}); })),
      dataset(p, "/continuum/{solver}/rho", "mass/length", "cell averages of the density at t",
              "when output.fields, for solvers that give a density",
              each_field([](const Result& c, Emitter& out) {
                if (!c.rho.empty()) out.values(c.rho, {c.solver});
              })),
      dataset(p, "/continuum/{solver}/shocks/x", "length", "shock positions", shocks,
              each(with_shocks([](const continuum::Shock& s) { return s.x; }))),
      dataset(p, "/continuum/{solver}/shocks/mass", "mass", "mass held in each shock", shocks,
              each(with_shocks([](const continuum::Shock& s) { return s.mass; }))),
      dataset(p, "/continuum/{solver}/shocks/jump", "length/time", "velocity jump v_right - v_left (< 0)",
              shocks, each(with_shocks([](const continuum::Shock& s) { return s.jump; }))),
      dataset(p, "/continuum/{solver}/shocks/v", "length/time", "shock velocities", shocks,
              each(with_shocks([](const continuum::Shock& s) { return s.v; }))),
      attribute(p, "/continuum/{solver}@label", "", "the solver's legend label (its registration)", "",
                each([info](const Result& c, Emitter& out) { out.text(info(c).label, {c.solver}); })),
      attribute(p, "/continuum/{solver}@colour", "", "the solver's plot colour (its registration)", "",
                each([info](const Result& c, Emitter& out) { out.text(info(c).colour, {c.solver}); })),
      attribute(
          p, "/continuum/{solver}@exact", "1",
          "1 for the exact solver (its registration), else 0: the plots draw it black and dashed as exact",
          "", each([info](const Result& c, Emitter& out) { out.number(info(c).exact ? 1 : 0, {c.solver}); })),
      attribute(p, "/continuum/{solver}@t", "time", "time of the fields", "",
                each([](const Result& c, Emitter& out) { out.number(c.t, {c.solver}); })),
      attribute(p, "/continuum/{solver}@method", "", "which path ran and why", "",
                each([](const Result& c, Emitter& out) { out.text(c.method_note, {c.solver}); })),
      attribute(p, "/continuum/{solver}@wall_seconds", "s", "wall-clock time of the solve", "",
                each([](const Result& c, Emitter& out) { out.number(c.wall_seconds, {c.solver}); })),
  };
}

std::vector<Declaration> comparison() {
  const Part p = Part::compare;
  auto snap = [](auto f) {
    return [f](const RunResults& r, Emitter& out) {
      if (r.comparison) f(r.comparison->snapshot, out);
    };
  };
  using Snap = compare::SnapshotComparison;
  return {
      attribute(p, "/compare@t", "time", "time of the compared states", "",
                snap([](const Snap& c, Emitter& out) { out.number(c.t); })),
      attribute(p, "/compare@min_mass", "mass", "the mass above which clusters and shocks are counted", "",
                snap([](const Snap& c, Emitter& out) { out.number(c.min_mass); })),
      dataset(p, "/compare/x", "length", "cell centres (the continuum grid)", "",
              snap([](const Snap& c, Emitter& out) { out.values(c.particle_fields.x); })),
      dataset(p, "/compare/rho_particles", "mass/length",
              "particle mass deposited on the grid (compare.deposit)", "",
              snap([](const Snap& c, Emitter& out) { out.values(c.particle_fields.rho); })),
      dataset(p, "/compare/v_particles", "length/time",
              "particle momentum / mass in the cells with mass (/compare/occupied = 1); an empty cell holds "
              "the velocity interpolated linearly (periodically) between its occupied neighbours, not data",
              "", snap([](const Snap& c, Emitter& out) { out.values(c.particle_fields.v); })),
      stored_as(
          Storage::integer,
          dataset(
              p, "/compare/occupied", "1",
              "1 where particle mass was deposited in the cell, 0 where /compare/v_particles is interpolated",
              "", snap([](const Snap& c, Emitter& out) {
                out.values(column(c.particle_fields.mass, [](double m) { return m > 0 ? 1.0 : 0.0; }));
              }))),
      dataset(p, "/compare/clusters_x", "length", "cluster positions", "",
              snap([](const Snap& c, Emitter& out) {
                out.values(column(c.clusters, [](auto& k) { return k.x; }));
              })),
      dataset(p, "/compare/clusters_m", "mass", "cluster masses", "", snap([](const Snap& c, Emitter& out) {
                out.values(column(c.clusters, [](auto& k) { return k.m; }));
              })),
      dataset(p, "/compare/clusters_v", "length/time", "cluster velocities", "",
              snap([](const Snap& c, Emitter& out) {
                out.values(column(c.clusters, [](auto& k) { return k.v; }));
              })),
      dataset(p, "/compare/shocks_x", "length", "shock positions (compare.solver)", "",
              snap([](const Snap& c, Emitter& out) {
                out.values(column(c.shocks, [](auto& s) { return s.x; }));
              })),
      dataset(p, "/compare/shocks_mass", "mass", "shock masses", "", snap([](const Snap& c, Emitter& out) {
                out.values(column(c.shocks, [](auto& s) { return s.mass; }));
              })),
      dataset(p, "/compare/shocks_jump", "length/time", "shock velocity jumps v_R - v_L", "",
              snap([](const Snap& c, Emitter& out) {
                out.values(column(c.shocks, [](auto& s) { return s.jump; }));
              })),
      stored_as(Storage::integer, dataset(p, "/compare/matched_shock", "1",
                                          "each matched pair's shock: its index in /compare/shocks_x", "",
                                          snap([](const Snap& c, Emitter& out) {
                                            out.values(column(c.match.pairs, [](auto& q) {
                                              return static_cast<double>(q.shock);
                                            }));
                                          }))),
      stored_as(Storage::integer, dataset(p, "/compare/matched_cluster", "1",
                                          "each matched pair's cluster: its index in /compare/clusters_x", "",
                                          snap([](const Snap& c, Emitter& out) {
                                            out.values(column(c.match.pairs, [](auto& q) {
                                              return static_cast<double>(q.cluster);
                                            }));
                                          }))),
      dataset(p, "/compare/matched_position_error", "length", "x_cluster - x_shock of each matched pair", "",
              snap([](const Snap& c, Emitter& out) {
                out.values(column(c.match.pairs, [](auto& q) { return q.position_error; }));
              })),
      dataset(p, "/compare/cluster_mass_edges", "mass",
              "bin edges 1.5, 2.5, 4.5, ..., 2^k + 0.5 of the clusters' masses (a lone particle is not a "
              "cluster)",
              "",
              [](const RunResults& r, Emitter& out) {
                if (r.comparison) out.values(r.comparison->mass_edges);
              }),
      stored_as(Storage::integer, dataset(p, "/compare/cluster_mass_count", "1",
                                          "clusters of the particle state in each mass bin", "",
                                          [](const RunResults& r, Emitter& out) {
                                            if (r.comparison) out.values(r.comparison->mass_count);
                                          })),
      dataset(
          p, "/compare/cluster_mass_exact", "1",
          "the exact expected number of shocks of Burgers turbulence from this white noise in each mass bin "
          "(shockgas/compare/shock_mass_law.hpp)",
          "when the start is white noise on a lattice",
          [](const RunResults& r, Emitter& out) {
            if (r.comparison && !r.comparison->mass_exact.empty()) out.values(r.comparison->mass_exact);
          }),
      dataset(p, "/compare/sawtooth_slope_times_t", "1",
              "slope of v on each ramp between shocks, times t (theory: 1)", "",
              snap([](const Snap& c, Emitter& out) {
                out.values(column(c.sawtooth.ramps, [](auto& q) { return q.slope_times_t; }));
              })),
  };
}

std::vector<Declaration> sweep() {
  const Part p = Part::sweep;
  auto each = [](auto f) {
    return [f](const RunResults& r, Emitter& out) {
      for (std::size_t k = 0; k < r.variants.size(); ++k)
        f(r.variants[k], out, std::vector{std::to_string(k)});
    };
  };
  auto hist = [](auto f) {
    return [f](const VariantResult& v, Emitter& out, const std::vector<std::string>& at) {
      if (v.histogram.bins > 0 && !v.histogram.t.empty()) f(v.histogram, out, at);
    };
  };
  const char* particles = "when the variants run particles";
  return {
      attribute(p, "/sweep@T_exponent_theory", "1", "theory: T ~ t^(-2/3) in the sticky-gas regime",
                particles,
                [](const RunResults& r, Emitter& out) {
                  for (const auto& v : r.variants)
                    if (!v.t.empty()) return out.number(compare::kStickyCoolingExponent);
                }),
      attribute(p, "/sweep/{k}@label", "", "variant k's label", "",
                each([](const VariantResult& v, Emitter& out, const auto& at) { out.text(v.label, at); })),
      attribute(p, "/sweep/{k}@set", "", "variant k's overrides", "",
                each([](const VariantResult& v, Emitter& out, const auto& at) { out.text(v.set, at); })),
      dataset(p, "/sweep/{k}/particles/t", "time", "variant k: log-spaced sample times", particles,
              each([](const VariantResult& v, Emitter& out, const auto& at) {
                if (!v.t.empty()) out.values(v.t, at);
              })),
      dataset(p, "/sweep/{k}/particles/T", "length^2/time^2", "variant k: temperature (ensemble mean)",
              particles, each([](const VariantResult& v, Emitter& out, const auto& at) {
                if (!v.t.empty()) out.values(v.T, at);
              })),
      dataset(p, "/sweep/{k}/particles/T_stderr", "length^2/time^2", "variant k: standard error of T",
              particles, each([](const VariantResult& v, Emitter& out, const auto& at) {
                if (!v.t.empty()) out.values(v.T_stderr, at);
              })),
      dataset(p, "/sweep/{k}/particles/histogram/z", "length/time^(2/3)", "variant k: bin centres of z",
              "when particles.histogram_bins > 0",
              each(hist([](const compare::ZHistogram& h, Emitter& out, const auto& at) {
                out.values(h.centres(), at);
              }))),
      dataset(p, "/sweep/{k}/particles/histogram/t", "time", "variant k: sample times of the histogram",
              "when particles.histogram_bins > 0",
              each(hist(
                  [](const compare::ZHistogram& h, Emitter& out, const auto& at) { out.values(h.t, at); }))),
      dataset(p, "/sweep/{k}/particles/histogram/density", "time^(2/3)/length",
              "variant k: mass-weighted density of z, ensemble mean (rows: times)",
              "when particles.histogram_bins > 0",
              each(hist([](const compare::ZHistogram& h, Emitter& out, const auto& at) {
                out.matrix(h.density, h.t.size(), h.bins, at);
              }))),
      dataset(p, "/sweep/{k}/particles/histogram/exact", "time^(2/3)/length",
              "variant k: the exact mass-weighted law of z of the sticky gas on the bins (as "
              "/particles/histogram/exact)",
              "when particles.histogram_bins > 0 and the start is white noise on a lattice",
              each([](const VariantResult& v, Emitter& out, const auto& at) {
                if (!v.histogram_exact.empty()) out.values(v.histogram_exact, at);
              })),
      attribute(p, "/sweep/{k}/particles@T_amplitude_exact", "length^2/time^(4/3)",
                "variant k: exact T t^(2/3) of the sticky gas (as /particles/analysis@T_amplitude_exact)",
                "when the start is white noise on a lattice",
                each([](const VariantResult& v, Emitter& out, const auto& at) {
                  if (v.temperature_amplitude_exact && !v.t.empty())
                    out.number(*v.temperature_amplitude_exact, at);
                })),
  };
}

}  // namespace

std::vector<Declaration> field_datasets() {
  std::vector<Declaration> d = analysis();
  append(d, continuum());
  append(d, comparison());
  append(d, sweep());
  return d;
}

}  // namespace shockgas::app::layout
