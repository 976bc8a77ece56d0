// shockgas.continuum: every registered solver on the caller's own data, and the
// registry itself.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <utility>

#include "arrays.hpp"
#include "bindings.hpp"
#include "interruptible.hpp"
#include "keywords.hpp"
#include "memory_check.hpp"
#include "shockgas/continuum/registry.hpp"
#include "shockgas/continuum/solve.hpp"
#include "shockgas/core/expression.hpp"

namespace shockgas::python {

namespace {

// Values constant on n equal cells of [0, length): value[floor(x n / length)].
std::function<double(double)> piecewise(std::vector<double> values, double length) {
  const double scale = static_cast<double>(values.size()) / length;
  return [values = std::move(values), scale](double x) {
    const auto i = static_cast<std::size_t>(std::max(0.0, std::floor(x * scale)));
    return values[std::min(i, values.size() - 1)];
  };
}

// The scene keys domain and L of [initial], read through their declarations;
// given: the values as passed (None where not).
InitialParams initial_keys(py::dict& keys, py::object& domain, py::object& L) {
  InitialParams ip;
  for (auto [key, given] : {std::pair{"domain", &domain}, std::pair{"L", &L}}) {
    *given = py::none();
    if (!keys.contains(key)) continue;
    *given = keys[key];
    initial_parameters().entry(key).set(ip, to_parameter(*given));
    PyDict_DelItem(keys.ptr(), py::str(key).ptr());
  }
  return ip;
}

// An argument that the form of the data does not use is refused, not ignored.
void refuse_unused(const char* key, const py::handle& value, const std::string& why) {
  if (!value.is_none()) throw InputError(key, std::string(py::str(py::repr(value))).substr(0, 80), why);
}

// The initial field from arrays of cell values (dx: the cells' width).
InitialField from_cells(const py::handle& v0, const py::handle& rho0, const py::handle& dx) {
  std::vector<double> v = to_vector(v0, "v0");
  require(v.size() >= 1, "v0", std::string("[]"), "an array of cell values");
  require(!dx.is_none(), "dx", std::string("None"), "the width of a cell of v0 [length], a number > 0");
  const double width = dx.cast<double>();
  require_above("dx", width, 0.0);
  InitialField f;
  f.length = width * static_cast<double>(v.size());
  f.pieces = v.size();
  if (!rho0.is_none()) {
    std::vector<double> rho = to_vector(rho0, "rho0");
    require(rho.size() == v.size(), "rho0", rho.size(),
            "one density per cell of v0 (" + std::to_string(v.size()) + ")");
    for (double r : rho) require(std::isfinite(r) && r >= 0, "rho0", r, "finite densities >= 0");
    f.rho0 = piecewise(std::move(rho), f.length);
  }
  for (double x : v) require(std::isfinite(x), "v0", x, "finite velocities");
  f.v0 = piecewise(std::move(v), f.length);
  return f;
}

// The initial field from expressions in x, read as the scene keys initial.v0,
// initial.rho0 on [0, initial.domain).
InitialField from_expressions(const py::handle& v0, const py::handle& rho0, const InitialParams& ip) {
  InitialParams p = ip;
  p.velocities = Velocities::expression;
  p.v0 = v0.cast<std::string>();
  if (!rho0.is_none()) p.rho0 = rho0.cast<std::string>();
  validate(p);
  return make_initial_field(p);
}

// The initial field of point masses at x with velocities v0 and masses m on the ring of length L.
InitialField from_bodies(const py::handle& x, const py::handle& v0, const py::handle& m,
                         const InitialParams& ip) {
  InitialField f;
  f.bodies.x = to_vector(x, "x");
  f.bodies.v = to_vector(v0, "v0");
  f.bodies.m = m.is_none() ? std::vector<double>(f.bodies.x.size(), 1.0) : to_vector(m, "m");
  const std::string n = std::to_string(f.bodies.x.size());
  require(f.bodies.v.size() == f.bodies.x.size(), "v0", f.bodies.v.size(),
          "one velocity per body (" + n + ")");
  require(f.bodies.m.size() == f.bodies.x.size(), "m", f.bodies.m.size(),
          "one mass per body (" + n + "), or None");
  f.length = ip.L > 0 ? ip.L : static_cast<double>(f.bodies.size());
  return f;
}

py::dict result_dict(continuum::ContinuumResult&& r) {
  py::dict d;
  d["solver"] = r.solver;
  d["t"] = r.t;
  d["length"] = r.length;
  d["x"] = to_numpy(std::move(r.x));
  d["v"] = to_numpy(std::move(r.v));
  d["rho"] = r.rho.empty() ? py::object(py::none()) : py::object(to_numpy(std::move(r.rho)));
  d["shocks"] = py::none();
  if (r.has_shocks) d["shocks"] = shocks_dict(r.shocks);
  d["method"] = r.method_note;
  d["stats"] = r.stats;
  d["wall_seconds"] = r.wall_seconds;
  return d;
}

py::dict solve(const std::string& name, const py::handle& v0, const py::handle& rho0, const py::handle& dx,
               const py::handle& x, const py::handle& m, const py::object& progress,
               const py::kwargs& kwargs) {
  py::dict keys(kwargs);
  if (keys.contains("solvers"))
    throw InputError("solvers", to_parameter(keys["solvers"]).written,
                     "no keyword: the solver is the argument name");
  py::object domain, L;
  const InitialParams ip = initial_keys(keys, domain, L);
  continuum::ContinuumParams p;
  continuum::parameters().set(p, "solvers", ParameterValue::of(name));
  const bool default_cells = !keys.contains("cells");
  take_keywords(p, continuum::parameters(), keys);
  refuse_leftover(keys, "shockgas.continuum.solve", continuum::parameters().keys_text() + ", domain, L");
  // The form of the data, and the arguments it does not use refused.
  InitialField f;
  if (!x.is_none()) {
    refuse_unused("rho0", rho0, "None with point masses (x): their masses are m");
    refuse_unused("dx", dx, "None with point masses (x): the cells are cells= cells of the ring [0, L)");
    refuse_unused("domain", domain, "no keyword with point masses (x): the ring's length is L");
    f = from_bodies(x, v0, m, ip);
  } else if (py::isinstance<py::str>(v0)) {
    refuse_unused("m", m, "None without x: the density of expressions is rho0");
    refuse_unused("dx", dx, "None with expressions: they are solved on cells= cells of [0, domain)");
    refuse_unused("L", L, "no keyword with expressions: their period is domain");
    f = from_expressions(v0, rho0, ip);
  } else {
    refuse_unused("m", m, "None without x: the density of cell values is rho0");
    refuse_unused("domain", domain, "no keyword with cell values: their length is len(v0) * dx");
    refuse_unused("L", L, "no keyword with cell values: their length is len(v0) * dx");
    f = from_cells(v0, rho0, dx);
  }
  if (f.pieces > 0 && default_cells) p.cells = f.pieces;
  require(f.pieces == 0 || p.cells % f.pieces == 0, "continuum.cells", p.cells,
          "a multiple of the cells of v0 (" + std::to_string(f.pieces) + ")");
  continuum::validate(p);
  check_memory_of(0, nullptr, &p);
  continuum::preflight(name, f, p, p.t_end);
  const std::string stage = "continuum/" + name;
  auto work = [&](ProgressRelay& relay) {
    relay.report(stage, 0.0, 0.0);
    auto r = continuum::solve(name, f, p, p.t_end, [&](double fraction, double t, std::uint64_t) {
      relay.report(stage, fraction, t);
    });
    relay.report(stage, 1.0, r.t);
    return r;
  };
  return result_dict(run_interruptible<continuum::ContinuumResult>(work, progress));
}

py::list solvers() {
  py::list out;
  for (const continuum::SolverInfo& s : continuum::registered_solvers())
    out.append(py::dict(py::arg("name") = s.name, py::arg("summary") = s.summary, py::arg("label") = s.label,
                        py::arg("colour") = s.colour, py::arg("density") = s.density,
                        py::arg("shocks") = s.shocks, py::arg("viscous") = s.viscous,
                        py::arg("exact") = s.exact, py::arg("by_default") = s.by_default));
  return out;
}

}  // namespace

py::dict shocks_dict(const std::vector<continuum::Shock>& shocks) {
  py::dict d;
  d["x"] = column(shocks, [](const continuum::Shock& s) { return s.x; });
  d["mass"] = column(shocks, [](const continuum::Shock& s) { return s.mass; });
  d["jump"] = column(shocks, [](const continuum::Shock& s) { return s.jump; });
  d["v"] = column(shocks, [](const continuum::Shock& s) { return s.v; });
  return d;
}

void bind_continuum(py::module_& continuum) {
  continuum.def("_solve", &solve, py::arg("name"), py::arg("v0"), py::arg("rho0") = py::none(),
                py::arg("dx") = py::none(), py::arg("x") = py::none(), py::arg("m") = py::none(),
                py::arg("progress") = py::none());
  continuum.def("_solvers", &solvers);
  continuum.attr("_keywords") = keyword_docs(continuum::parameters());
}

}  // namespace shockgas::python
