// shockgas.compare: shocks of a field, clusters of a state, their matching, the
// particles on a grid, sawtooth slopes, and the whole comparison of one snapshot,
// with the options of the scene's [compare] keys.
#include <pybind11/pybind11.h>

#include "arrays.hpp"
#include "bindings.hpp"
#include "keywords.hpp"
#include "memory_check.hpp"
#include "shockgas/compare/snapshot_comparison.hpp"
#include "shockgas/particles/params.hpp"

namespace shockgas::python {

namespace {

using continuum::Shock;
using particles::Cluster;

Bodies state_from(const py::handle& x, const py::handle& v, const py::handle& m) {
  Bodies b{to_vector(x, "x"), to_vector(v, "v"), {}};
  b.m = m.is_none() ? std::vector<double>(b.x.size(), 1.0) : to_vector(m, "m");
  const std::string equal = "len(x) = " + std::to_string(b.x.size());
  require(b.v.size() == b.x.size(), "len(v)", b.v.size(), equal);
  require(b.m.size() == b.x.size(), "len(m)", b.m.size(), equal);
  return b;
}

std::vector<Shock> shocks_from(const py::handle& shocks) {
  const auto d = py::reinterpret_borrow<py::object>(shocks);  // a dict or a record
  const std::vector<double> x = to_vector(d["x"], "shocks.x");
  const std::vector<double> mass = to_vector(d["mass"], "shocks.mass");
  const std::vector<double> jump = to_vector(d["jump"], "shocks.jump");
  const std::vector<double> v = to_vector(d["v"], "shocks.v");
  require(mass.size() == x.size() && jump.size() == x.size() && v.size() == x.size(), "shocks", x.size(),
          "columns x, mass, jump, v of equal lengths");
  std::vector<Shock> out(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) out[i] = {x[i], mass[i], jump[i], v[i]};
  return out;
}

py::dict clusters_dict(const std::vector<Cluster>& clusters) {
  py::dict d;
  d["x"] = column(clusters, [](const Cluster& c) { return c.x; });
  d["v"] = column(clusters, [](const Cluster& c) { return c.v; });
  d["m"] = column(clusters, [](const Cluster& c) { return c.m; });
  d["first"] = column(clusters, [](const Cluster& c) { return c.first; });
  d["count"] = column(clusters, [](const Cluster& c) { return c.count; });
  return d;
}

std::vector<Cluster> clusters_from(const py::handle& clusters) {
  const auto d = py::reinterpret_borrow<py::object>(clusters);
  const std::vector<double> x = to_vector(d["x"], "clusters.x"), v = to_vector(d["v"], "clusters.v"),
                            m = to_vector(d["m"], "clusters.m");
  require(v.size() == x.size() && m.size() == x.size(), "clusters", x.size(),
          "columns x, v, m of equal lengths");
  std::vector<Cluster> out(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) out[i] = {0, 0, x[i], v[i], m[i]};
  return out;
}

py::dict match_dict(const compare::MatchResult& r) {
  using compare::MatchedPair;
  py::dict d;
  d["shock"] = column(r.pairs, [](const MatchedPair& p) { return p.shock; });
  d["cluster"] = column(r.pairs, [](const MatchedPair& p) { return p.cluster; });
  d["position_error"] = column(r.pairs, [](const MatchedPair& p) { return p.position_error; });
  d["mass_error"] = column(r.pairs, [](const MatchedPair& p) { return p.mass_error; });
  d["velocity_error"] = column(r.pairs, [](const MatchedPair& p) { return p.velocity_error; });
  d["unmatched_shocks"] = column(r.unmatched_shocks, [](std::size_t i) { return i; });
  d["unmatched_clusters"] = column(r.unmatched_clusters, [](std::size_t i) { return i; });
  d["eligible_shocks"] = r.eligible_shocks;
  d["eligible_clusters"] = r.eligible_clusters;
  d["matched_mass_fraction"] = r.matched_mass_fraction;
  d["max_position_error"] = r.max_position_error;
  d["rms_position_error"] = r.rms_position_error;
  d["max_distance"] = r.max_distance;
  d["max_relative_mass_error"] = r.max_relative_mass_error;
  d["rms_velocity_error"] = r.rms_velocity_error;
  return d;
}

py::dict sawtooth_dict(const compare::SawtoothFit& f) {
  using compare::RampFit;
  py::dict d;
  d["x_begin"] = column(f.ramps, [](const RampFit& r) { return r.x_begin; });
  d["x_end"] = column(f.ramps, [](const RampFit& r) { return r.x_end; });
  d["cells"] = column(f.ramps, [](const RampFit& r) { return r.cells; });
  d["slope"] = column(f.ramps, [](const RampFit& r) { return r.slope; });
  d["slope_error"] = column(f.ramps, [](const RampFit& r) { return r.slope_error; });
  d["slope_times_t"] = column(f.ramps, [](const RampFit& r) { return r.slope_times_t; });
  d["median_slope_times_t"] = f.slope_times_t.median;
  return d;
}

py::dict fields_dict(compare::GridFields&& g) {
  py::dict d;
  d["x"] = to_numpy(std::move(g.x));
  d["rho"] = to_numpy(std::move(g.rho));
  d["v"] = to_numpy(std::move(g.v));
  d["mass"] = to_numpy(std::move(g.mass));
  d["momentum"] = to_numpy(std::move(g.momentum));
  return d;
}

// The restitution and threshold of the gas (scene keys particles.r, .delta) and
// the [compare] keys, from the keywords.
struct SnapshotKeys {
  particles::ParticleParams gas;
  compare::CompareParams compare;
};
SnapshotKeys snapshot_keys(py::dict& keys, const std::string& function) {
  SnapshotKeys k;
  for (const char* key : {"r", "delta"}) {
    if (!keys.contains(key)) continue;
    particles::parameters().entry(key).set(k.gas, to_parameter(keys[key]));
    PyDict_DelItem(keys.ptr(), py::str(key).ptr());
  }
  take_keywords(k.compare, compare::parameters(), keys);
  refuse_leftover(keys, function, "r, delta, " + compare::parameters().keys_text());
  return k;
}

py::dict detect_shocks(const py::handle& v, const py::handle& rho, double length, double min_jump,
                       const py::handle& max_width_cells) {
  const std::vector<double> vv = to_vector(v, "v");
  const std::vector<double> rr = rho.is_none() ? std::vector<double>{} : to_vector(rho, "rho");
  const std::size_t width = to_count(max_width_cells, "compare.max_width_cells", 1);
  return shocks_dict(compare::detect_shocks(vv, rr, length, {min_jump, width}));
}

py::dict find_clusters(const py::handle& x, const py::handle& v, const py::handle& m, double L, double t,
                       const py::kwargs& kwargs) {
  py::dict keys(kwargs);
  const SnapshotKeys k = snapshot_keys(keys, "shockgas.compare.find_clusters");
  require(std::isfinite(L) && L > 0, "L", L, "> 0 (the ring's length)");
  require(std::isfinite(t) && t >= 0, "t", t, ">= 0");
  const Bodies b = state_from(x, v, m);
  require(b.size() >= 1, "x", b.size(), "at least one body");
  const double spacing = L / static_cast<double>(b.size());
  const auto criteria = compare::snapshot_params(k.compare, k.gas.r, k.gas.delta, spacing, t).clusters;
  return clusters_dict(particles::find_clusters(b, L, criteria));
}

py::dict match(const py::handle& shocks, const py::handle& clusters, double L, double max_distance,
               double min_mass) {
  return match_dict(compare::match_shocks_to_clusters(shocks_from(shocks), clusters_from(clusters), L,
                                                      {max_distance, min_mass}));
}

py::dict deposit(const py::handle& x, const py::handle& v, const py::handle& m, double length,
                 const py::handle& cells, const std::string& scheme) {
  const auto s = compare::parse_deposit_scheme(scheme, "compare.deposit");
  const std::size_t n = to_count(cells, "compare.cells", 1);
  check_bytes(5.0 * sizeof(double) * static_cast<double>(n), "x, rho, v, mass and momentum of each cell",
              "compare.cells", static_cast<double>(n));
  return fields_dict(compare::deposit_on_grid(state_from(x, v, m), length, n, s));
}

py::dict sawtooth(const py::handle& v, double length, double t, const py::handle& shock_x,
                  const py::handle& weights, const py::handle& skip_cells, const py::handle& min_cells) {
  const std::vector<double> w = weights.is_none() ? std::vector<double>{} : to_vector(weights, "weights");
  const compare::SawtoothParams fit{to_count(skip_cells, "compare.sawtooth.skip_cells", 0),
                                    to_count(min_cells, "compare.sawtooth.min_cells", 2)};
  return sawtooth_dict(
      compare::fit_sawtooth_slopes(to_vector(v, "v"), length, t, to_vector(shock_x, "shock_x"), fit, w));
}

continuum::ContinuumResult field_from(const py::handle& field) {
  const auto d = py::reinterpret_borrow<py::object>(field);
  continuum::ContinuumResult f;
  f.solver = d["solver"].cast<std::string>();
  f.t = d["t"].cast<double>();
  f.length = d["length"].cast<double>();
  f.x = to_vector(d["x"], "field.x");
  f.v = to_vector(d["v"], "field.v");
  if (!d["rho"].is_none()) f.rho = to_vector(d["rho"], "field.rho");
  const std::string cells = "len(field.x) = " + std::to_string(f.x.size());
  require(f.v.size() == f.x.size(), "len(field.v)", f.v.size(), cells);
  require(f.rho.empty() || f.rho.size() == f.x.size(), "len(field.rho)", f.rho.size(), cells);
  f.has_shocks = !d["shocks"].is_none();
  if (f.has_shocks) f.shocks = shocks_from(d["shocks"]);
  return f;
}

py::dict snapshot(const py::handle& x, const py::handle& v, const py::handle& m, const py::handle& field,
                  const py::handle& N_given, const py::kwargs& kwargs) {
  const std::size_t N = to_count(N_given, "initial.N", 1);
  py::dict keys(kwargs);
  const SnapshotKeys k = snapshot_keys(keys, "shockgas.compare.snapshot");
  const Bodies state = state_from(x, v, m);
  const continuum::ContinuumResult f = field_from(field);
  const double spacing = f.length / static_cast<double>(N > 0 ? N : 1);
  compare::SnapshotComparison c = compare::compare_snapshot(
      state, N, f, compare::snapshot_params(k.compare, k.gas.r, k.gas.delta, spacing, f.t));
  py::dict d;
  d["t"] = c.t;
  d["min_mass"] = c.min_mass;
  d["particle_fields"] = fields_dict(std::move(c.particle_fields));
  d["clusters"] = clusters_dict(c.clusters);
  d["shocks"] = shocks_dict(c.shocks);
  d["match"] = match_dict(c.match);
  d["sawtooth"] = sawtooth_dict(c.sawtooth);
  d["particle_sawtooth"] = sawtooth_dict(c.particle_sawtooth);
  d["n_shocks"] = c.n_shocks;
  d["n_clusters"] = c.n_clusters;
  d["shock_count_ratio"] = c.shock_count_ratio;
  return d;
}

}  // namespace

void bind_compare(py::module_& compare) {
  compare.def("_detect_shocks", &detect_shocks, py::arg("v"), py::arg("rho"), py::arg("length"),
              py::arg("min_jump"), py::arg("max_width_cells"));
  compare.def("_find_clusters", &find_clusters, py::arg("x"), py::arg("v"), py::arg("m"), py::arg("L"),
              py::arg("t"));
  compare.def("_match", &match, py::arg("shocks"), py::arg("clusters"), py::arg("L"), py::arg("max_distance"),
              py::arg("min_mass"));
  compare.def("_deposit", &deposit, py::arg("x"), py::arg("v"), py::arg("m"), py::arg("length"),
              py::arg("cells"), py::arg("scheme"));
  compare.def("_sawtooth", &sawtooth, py::arg("v"), py::arg("length"), py::arg("t"), py::arg("shock_x"),
              py::arg("weights"), py::arg("skip_cells"), py::arg("min_cells"));
  compare.def("_snapshot", &snapshot, py::arg("x"), py::arg("v"), py::arg("m"), py::arg("field"),
              py::arg("N"));
  compare.attr("_keywords") = keyword_docs(compare::parameters());
}

}  // namespace shockgas::python
