// shockgas.particles.simulate and shockgas.hull: the engine and the exact
// sticky gas on the caller's own bodies.
#include <pybind11/pybind11.h>

#include <algorithm>
#include <cstdint>
#include <span>

#include "arrays.hpp"
#include "bindings.hpp"
#include "interruptible.hpp"
#include "keywords.hpp"
#include "memory_check.hpp"
#include "shockgas/compare/particle_analysis.hpp"
#include "shockgas/core/sticky_hull.hpp"
#include "shockgas/particles/simulate.hpp"

namespace shockgas::python {

namespace {

// Bodies from the caller's arrays, copied once; m = None: unit masses.
Bodies bodies_from(const py::handle& x, const py::handle& v, const py::handle& m) {
  Bodies b;
  b.x = to_vector(x, "x");
  b.v = to_vector(v, "v");
  b.m = m.is_none() ? std::vector<double>(b.x.size(), 1.0) : to_vector(m, "m");
  const std::string n = std::to_string(b.x.size());
  require(b.v.size() == b.x.size(), "v", b.v.size(), "as many velocities as positions (" + n + ")");
  require(b.m.size() == b.x.size(), "m", b.m.size(), "as many masses as positions (" + n + "), or None");
  return b;
}

// The ring length: the scene key initial.L (0 or absent: N, the mean spacing 1).
double ring_length(py::dict& keys, std::size_t n) {
  InitialParams ip;
  if (keys.contains("L")) {
    initial_parameters().entry("L").set(ip, to_parameter(keys["L"]));
    PyDict_DelItem(keys.ptr(), py::str("L").ptr());
  }
  return shockgas::ring_length(ip.L, n);
}

py::dict bodies_dict(Bodies&& b) {
  py::dict d;
  d["x"] = to_numpy(std::move(b.x));
  d["v"] = to_numpy(std::move(b.v));
  d["m"] = to_numpy(std::move(b.m));
  return d;
}

py::dict run_dict(particles::RunResult&& r) {
  py::dict d;
  r.series.for_each_column(
      [&](const char* name, std::vector<double>& column) { d[name] = to_numpy(std::move(column)); });
  d["final"] = bodies_dict(std::move(r.final_state));
  py::list snapshots;
  for (auto& s : r.snapshots) {
    py::dict snap = bodies_dict(std::move(s.bodies));
    snap["t"] = s.t;
    snapshots.append(snap);
  }
  d["snapshots"] = snapshots;
  d["histogram"] = py::none();
  if (auto& h = r.histogram; h.bins > 0) {
    const compare::ZHistogram z{h.zmax, h.bins, h.t, {}};
    const auto rows = static_cast<py::ssize_t>(h.t.size()), cols = static_cast<py::ssize_t>(h.bins);
    d["histogram"] = py::dict(py::arg("z") = to_numpy(z.centres()), py::arg("t") = to_numpy(std::move(h.t)),
                              py::arg("density") = to_numpy(std::move(h.density), {rows, cols}));
  }
  d["spacetime"] = py::none();
  if (auto& s = r.spacetime; !s.t.empty()) {
    const auto rows = static_cast<py::ssize_t>(s.t.size()), cols = static_cast<py::ssize_t>(s.labels.size());
    d["spacetime"] = py::dict(
        py::arg("label") = to_numpy(std::vector<std::int64_t>(s.labels.begin(), s.labels.end())),
        py::arg("t") = to_numpy(std::move(s.t)), py::arg("x") = to_numpy(std::move(s.x), {rows, cols}));
  }
  d["stop"] = py::dict(py::arg("reason") = particles::to_string(r.stop.reason), py::arg("time") = r.stop.time,
                       py::arg("position") = r.stop.position);
  d["total_collisions"] = r.collisions;
  d["wall_seconds"] = r.wall_seconds;
  return d;
}

py::dict simulate(const py::handle& x, const py::handle& v, const py::handle& m, const py::object& progress,
                  const py::kwargs& kwargs) {
  py::dict keys(kwargs);
  particles::ParticleParams p;
  take_keywords(p, particles::parameters(), keys);
  Bodies b = bodies_from(x, v, m);
  const double L = ring_length(keys, b.size());
  refuse_leftover(keys, "shockgas.particles.simulate", particles::parameters().keys_text() + ", L");
  particles::validate(p);
  require(p.realizations == 1, "particles.realizations", p.realizations,
          "1: simulate runs the given bodies once (an ensemble: shockgas.particles.ensemble)");
  check_memory_of(b.size(), &p, nullptr);
  auto work = [&](ProgressRelay& relay) {
    relay.report("particles", 0.0, 0.0);
    auto r = particles::simulate(b, L, p,
                                 [&](double f, double t, std::uint64_t) { relay.report("particles", f, t); });
    relay.report("particles", 1.0, r.stop.time);
    return r;
  };
  return run_dict(run_interruptible<particles::RunResult>(work, progress));
}

// A float64 array that the caller's array-like is, or becomes (ensure: no copy
// when it already is a contiguous float64 array).
using Doubles = py::array_t<double, py::array::c_style | py::array::forcecast>;
Doubles doubles(const py::handle& a, const std::string& key) {
  Doubles d = Doubles::ensure(a);
  if (!d || d.ndim() != 1) throw InputError(key, "(not a 1-D array of numbers)", "a 1-D array of numbers");
  return d;
}

struct ClusterColumns {
  std::vector<double> x, v, m;
  std::vector<std::uint64_t> first, count;
};

// The clusters at t, sorted by x (those of sticky_clusters_line / _ring), written
// straight into columns.
ClusterColumns sticky_columns(BodiesView b, bool ring, double L, double t) {
  const StickyHull h = ring ? StickyHull::ring(b, L, t) : StickyHull::line(b, t);
  ClusterColumns c;
  for (auto* col : {&c.x, &c.v, &c.m}) col->resize(h.size());
  for (auto* col : {&c.first, &c.count}) col->resize(h.size());
  std::size_t k = 0;
  h.for_each_by_x([&](const StickyCluster& s) {
    c.x[k] = s.x, c.v[k] = s.v, c.m[k] = s.m, c.first[k] = s.first, c.count[k] = s.count;
    ++k;
  });
  return c;
}

// The bodies are read in place (the hull does not change them): no copy.
py::dict hull(const py::handle& x, const py::handle& v, const py::handle& m, double t,
              const py::kwargs& kwargs) {
  py::dict keys(kwargs);
  particles::ParticleParams p;
  if (keys.contains("geometry")) {
    particles::parameters().entry("geometry").set(p, to_parameter(keys["geometry"]));
    PyDict_DelItem(keys.ptr(), py::str("geometry").ptr());
  }
  const Doubles xs = doubles(x, "x"), vs = doubles(v, "v");
  Doubles ms = m.is_none() ? Doubles(xs.size()) : doubles(m, "m");
  if (m.is_none()) std::fill_n(ms.mutable_data(), ms.size(), 1.0);
  const std::string n = std::to_string(xs.size());
  require(vs.size() == xs.size(), "v", vs.size(), "as many velocities as positions (" + n + ")");
  require(ms.size() == xs.size(), "m", ms.size(), "as many masses as positions (" + n + "), or None");
  const bool ring = p.geometry == particles::Geometry::ring;
  const double L = ring_length(keys, xs.size());
  refuse_leftover(keys, "shockgas.hull", "geometry, L");
  const auto span = [](const Doubles& a) { return std::span<const double>(a.data(), a.size()); };
  ClusterColumns c = [&] {
    py::gil_scoped_release nogil;  // O(N): not worth a worker thread
    return sticky_columns(BodiesView(span(xs), span(vs), span(ms)), ring, L, t);
  }();
  py::dict d;
  d["x"] = to_numpy(std::move(c.x));
  d["v"] = to_numpy(std::move(c.v));
  d["m"] = to_numpy(std::move(c.m));
  d["first"] = to_numpy(std::move(c.first));
  d["count"] = to_numpy(std::move(c.count));
  d["t"] = t;
  return d;
}

// Realization k of the scene keys' initial condition ([initial]), as bodies.
py::dict initial_bodies(const py::handle& realization, const py::kwargs& kwargs) {
  const std::size_t k = to_count(realization, "realization", 0);
  py::dict keys(kwargs);
  InitialParams ip;
  take_keywords(ip, initial_parameters(), keys);
  refuse_leftover(keys, "shockgas.particles.initial_bodies", initial_parameters().keys_text());
  validate(ip);
  check_bytes(app::kBodyBytes * static_cast<double>(ip.N), "the bodies", "initial.N",
              static_cast<double>(ip.N));
  py::dict d = bodies_dict(make_initial_bodies(ip, k));
  d["L"] = domain_length(ip);
  return d;
}

}  // namespace

void bind_particles(py::module_& m, py::module_& particles) {
  particles.def("_simulate", &simulate, py::arg("x"), py::arg("v"), py::arg("m") = py::none(),
                py::arg("progress") = py::none());
  m.def("_hull", &hull, py::arg("x"), py::arg("v"), py::arg("m") = py::none(), py::arg("t") = 0.0);
  particles.def("_initial_bodies", &initial_bodies, py::arg("realization") = 0);
  particles.attr("_keywords") = keyword_docs(particles::parameters());
  particles.attr("_initial_keywords") = keyword_docs(initial_parameters());
}

}  // namespace shockgas::python
