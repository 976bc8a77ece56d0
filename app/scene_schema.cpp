#include "scene_schema.hpp"

#include <cmath>
#include <sstream>

#include "shockgas/core/error.hpp"

namespace shockgas::app {

namespace {

using Kind = const char*;
static_assert(std::is_same_v<std::size_t, std::uint64_t>, "counts and seeds share one reader");

std::string quote(const std::string& s) {
  std::ostringstream out;
  out << toml::value<std::string>(s);
  return out.str();
}

std::string print_value(double v) { return std::isfinite(v) ? to_text(v) : "nan"; }
std::string print_value(std::size_t v) { return std::to_string(v); }
std::string print_value(bool v) { return v ? "true" : "false"; }
std::string print_value(const std::string& v) { return quote(v); }
template <class T>
std::string print_value(const std::vector<T>& v) {
  std::string s = "[";
  for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + print_value(v[i]);
  return s + "]";
}

[[noreturn]] void wrong_type(const std::string& key, const toml::node& node, const std::string& kind) {
  throw InputError(key, node_text(node), "a " + kind);
}

void read_value(const std::string& key, const toml::node& n, double& out) {
  if (auto f = n.value_exact<double>()) {
    out = *f;
  } else if (auto i = n.value_exact<std::int64_t>()) {
    out = static_cast<double>(*i);
  } else {
    wrong_type(key, n, "number");
  }
  // Ranges are checked by the parts' validate(); non-finite numbers are refused everywhere.
  if (!std::isfinite(out)) throw InputError(key, node_text(n), "a finite number");
}

void read_value(const std::string& key, const toml::node& n, std::uint64_t& out) {
  if (auto i = n.value_exact<std::int64_t>(); i && *i >= 0) {
    out = static_cast<std::uint64_t>(*i);
  } else if (auto f = n.value_exact<double>(); f && *f >= 0 && *f == std::floor(*f) && *f < 9e18) {
    out = static_cast<std::uint64_t>(*f);  // 1e5 is accepted where an integer is meant
  } else {
    wrong_type(key, n, "non-negative integer");
  }
}

void read_value(const std::string& key, const toml::node& n, bool& out) {
  if (auto b = n.value_exact<bool>()) out = *b;
  else wrong_type(key, n, "boolean (true or false)");
}

void read_value(const std::string& key, const toml::node& n, std::string& out) {
  if (auto s = n.value_exact<std::string>()) out = *s;
  else wrong_type(key, n, "string");
}

template <class T>
void read_value(const std::string& key, const toml::node& n, std::vector<T>& out) {
  out.clear();
  if (const auto* arr = n.as_array()) {
    for (const auto& item : *arr) {
      T value{};
      read_value(key, item, value);
      out.push_back(value);
    }
  } else {  // a single value stands for a list of one
    T value{};
    read_value(key, n, value);
    out.push_back(value);
  }
}

template <class T>
KeySpec key(std::string table, std::string name, Kind kind, std::string unit, std::string allowed,
            std::string doc, T& (*get)(Scene&)) {
  KeySpec spec{table, name, kind, std::move(unit), std::move(allowed), std::move(doc), {}, {}};
  const std::string dotted = spec.dotted();
  spec.read = [dotted, get](const toml::node& n, Scene& s) {
    read_value(dotted, n, get(s));
  };
  spec.print = [get](const Scene& s) { return print_value(get(const_cast<Scene&>(s))); };
  return spec;
}

#define SG_FIELD(part, field) +[](Scene& s) -> auto& { return s.part.field; }
#define SG_TOP(field) +[](Scene& s) -> auto& { return s.field; }

std::vector<KeySpec> build_schema() {
  return {
      key("scene", "name", "string", "", "any text; empty = the file's name", "scene name; results go to out/<name>/",
          SG_TOP(name)),
      key("scene", "description", "string", "", "any text", "what the scene shows", SG_TOP(description)),
      key("scene", "expected_runtime", "string", "", "any text", "wall time on a 2-core machine",
          SG_TOP(expected_runtime)),
      key("initial", "N", "integer", "1", "an integer N >= 2", "number of particles", SG_FIELD(initial, N)),
      key("initial", "positions", "string", "", "\"lattice\" or \"random\"",
          "initial positions: equally spaced, or uniform random (sorted)", SG_FIELD(initial, positions)),
      key("initial", "velocities", "string", "", "\"uniform\", \"gaussian\", \"file\" or \"expression\"",
          "initial velocities: uniform on [-amplitude, amplitude], Gaussian (sd amplitude), from file, or v0(x)",
          SG_FIELD(initial, velocities)),
      key("initial", "amplitude", "number", "length/time", "a finite number > 0", "velocity scale",
          SG_FIELD(initial, amplitude)),
      key("initial", "remove_mean", "boolean", "", "true or false", "subtract the mean velocity",
          SG_FIELD(initial, remove_mean)),
      key("initial", "file", "string", "", "an existing text file", "bodies `x v [m]` per line, sorted by x",
          SG_FIELD(initial, file)),
      key("initial", "seed", "integer", "", "an integer >= 0", "random seed (realization k uses a seed derived from it)",
          SG_FIELD(initial, seed)),
      key("initial", "L", "number", "length", "a finite number >= 0", "ring length; 0 means L = N (unit spacing)",
          SG_FIELD(initial, L)),
      key("initial", "v0", "string", "length/time", "an expression in x, finite on the domain",
          "v0(x) for velocities = \"expression\"", SG_FIELD(initial, v0)),
      key("initial", "rho0", "string", "mass/length", "an expression in x, > 0 on the domain",
          "rho0(x) for velocities = \"expression\"", SG_FIELD(initial, rho0)),
      key("initial", "domain", "number", "length", "a finite number > 0",
          "period of v0, rho0 (domain [0, domain)) for velocities = \"expression\"", SG_FIELD(initial, domain)),

      key("particles", "r", "number", "1", "a finite number in [0, 1]", "restitution coefficient; 0 = aggregation",
          SG_FIELD(particles, r)),
      key("particles", "delta", "number", "length/time", "a finite number >= 0",
          "velocity threshold below which collisions are sub-threshold; 0 = none", SG_FIELD(particles, delta)),
      key("particles", "subthreshold", "string", "", "\"elastic\" or \"sticky\"",
          "what a sub-threshold collision does", SG_FIELD(particles, subthreshold)),
      key("particles", "geometry", "string", "", "\"ring\" or \"line\"", "periodic ring of length L, or open line",
          SG_FIELD(particles, geometry)),
      key("particles", "solver", "string", "", "\"events\" or \"hull\" (hull: r = 0 only)",
          "event-driven simulation, or the exact sticky solution by the convex hull", SG_FIELD(particles, solver)),
      key("particles", "schedule", "string", "", "\"auto\", \"windows\" or \"global\"",
          "event order: time windows over stretches of the chain (the same collisions; equal masses without "
          "merges or collapse), the global queue, or auto = windows where they apply",
          SG_FIELD(particles, schedule)),
      key("particles", "t_end", "number", "time", "a finite number > 0", "final time", SG_FIELD(particles, t_end)),
      key("particles", "samples", "integer", "1", "an integer >= 1", "log-spaced sample times in [1, t_end]",
          SG_FIELD(particles, samples)),
      key("particles", "realizations", "integer", "1", "an integer >= 1", "independent realizations (ensemble)",
          SG_FIELD(particles, realizations)),
      key("particles", "threads", "integer", "1", "an integer >= 0", "worker threads; 0 = all cores",
          SG_FIELD(particles, threads)),
      key("particles", "snapshots", "list of numbers", "time", "times in [0, t_end]",
          "times at which x, v, m are stored", SG_FIELD(particles, snapshots)),
      key("particles", "spacetime", "boolean", "", "true or false", "record trajectories (space-time diagram)",
          SG_FIELD(particles, spacetime)),
      key("particles", "histogram_bins", "integer", "1", "an integer >= 0",
          "bins of the scaled velocity histogram z = v t^(1/3); 0 = none", SG_FIELD(particles, histogram_bins)),
      key("particles", "histogram_zmax", "number", "length/time^(2/3)", "a finite number > 0",
          "histogram range |z| <= zmax", SG_FIELD(particles, histogram_zmax)),
      key("particles", "spacetime_frames", "integer", "1", "an integer >= 2",
          "frames of the space-time record, equally spaced in [0, t_end]", SG_FIELD(particles, spacetime_frames)),
      key("particles", "clusters", "boolean", "", "true or false",
          "count clusters (default criteria) at the sample times", SG_FIELD(particles, clusters)),
      key("particles", "max_collisions", "integer", "1", "an integer >= 0",
          "stop a realization after this many collisions; 0 = no limit", SG_FIELD(particles, max_collisions)),
      key("particles", "max_wall_seconds", "number", "s", "a finite number >= 0",
          "stop a realization after this wall-clock time; 0 = no limit", SG_FIELD(particles, max_wall_seconds)),

      key("continuum", "solvers", "list of strings", "",
          "a list from \"godunov\", \"godunov2\", \"pressureless\", \"hopf_lax\", \"hopf_cole\", \"cvode\", \"arkode\"",
          "continuum solvers to run", SG_FIELD(continuum, solvers)),
      key("continuum", "cells", "integer", "1", "an integer >= 8", "grid cells on the domain",
          SG_FIELD(continuum, cells)),
      key("continuum", "cfl", "number", "1", "a Courant number in (0, 1]", "Courant number of the finite-volume schemes",
          SG_FIELD(continuum, cfl)),
      key("continuum", "nu", "number", "length^2/time", "a finite number > 0",
          "viscosity of hopf_cole, cvode, arkode", SG_FIELD(continuum, nu)),
      key("continuum", "t_end", "number", "time", "a finite number >= 0", "final time; 0 = particles.t_end",
          SG_FIELD(continuum, t_end)),
      key("continuum", "rtol", "number", "1", "a finite number in [1e-12, 0.1]", "relative tolerance of cvode, arkode",
          SG_FIELD(continuum, rtol)),
      key("continuum", "hopf_cole_path", "string", "", "\"auto\", \"fft\" or \"log\"",
          "Hopf-Cole evaluation: spectral heat equation, log-domain heat kernel, or chosen by its roundoff bound",
          SG_FIELD(continuum, hopf_cole_path)),
      key("continuum", "limiter", "string", "", "\"minmod\", \"vanleer\" or \"mc\"", "slope limiter of godunov2",
          SG_FIELD(continuum, limiter)),
      key("continuum", "boundary", "string", "", "\"periodic\" or \"outflow\"", "boundary condition",
          SG_FIELD(continuum, boundary)),
      key("continuum", "allow_unstable", "boolean", "", "true or false",
          "run even outside a method's stable range (for stability studies)", SG_FIELD(continuum, allow_unstable)),

      key("compare", "solver", "string", "", "one of continuum.solvers",
          "the continuum solver whose shocks are matched to the clusters", SG_FIELD(compare, solver)),
      key("compare", "deposit", "string", "", "\"ngp\" or \"cic\"", "particles -> grid: nearest cell or cloud in cell",
          SG_FIELD(compare, deposit)),
      key("compare", "match_distance", "number", "length", "a finite number >= 0",
          "largest shock-cluster distance of a match; 0 = automatic", SG_FIELD(compare, match_distance)),
      key("compare", "min_cluster_particles", "number", "1", "a finite number >= 0",
          "clusters and shocks lighter than this many mean particle masses are not counted; 0 = max(2, t^(2/3)/10)",
          SG_FIELD(compare, min_cluster_particles)),
      key("compare", "cluster_gap", "number", "length", "a finite number >= 0",
          "largest gap inside a cluster; 0 = derived from delta and the spacing", SG_FIELD(compare, cluster_gap)),
      key("compare", "cluster_dv", "number", "length/time", "a finite number >= 0",
          "largest relative velocity inside a cluster; 0 = derived from delta", SG_FIELD(compare, cluster_dv)),
      key("compare", "distribution_t_min", "number", "time", "a finite number >= 0",
          "scaled velocity distributions are compared at sample times >= this",
          SG_FIELD(compare, distribution_t_min)),
      key("compare", "fit_window", "number", "1", "a finite number > 1",
          "the T(t) exponent is fitted on [t_end / fit_window, t_end]", SG_FIELD(compare, fit_window)),

      key("sweep", "variants", "list of strings", "", "overrides \"table.key=value; ...\" per variant",
          "run the scene once per variant, side by side", SG_FIELD(sweep, variants)),
      key("sweep", "labels", "list of strings", "", "one label per variant, or empty",
          "variant labels for tables and plots", SG_FIELD(sweep, labels)),
      key("sweep", "reference_key", "string", "", "a summary.json key, or empty",
          "the result compared with reference_values in the report", SG_FIELD(sweep, reference_key)),
      key("sweep", "reference_values", "list of strings", "", "one text per variant (\"\" for none), or empty",
          "published values of reference_key", SG_FIELD(sweep, reference_values)),
      key("sweep", "reference_source", "string", "", "any text", "where the reference values come from",
          SG_FIELD(sweep, reference_source)),

      key("output", "plots", "boolean", "", "true or false", "make PNG plots", SG_FIELD(output, plots)),
      key("output", "fields", "boolean", "", "true or false", "store the continuum fields in result.h5",
          SG_FIELD(output, fields)),
  };
}

#undef SG_FIELD
#undef SG_TOP

}  // namespace

const std::vector<KeySpec>& scene_schema() {
  static const std::vector<KeySpec> schema = build_schema();
  return schema;
}

const std::vector<TableSpec>& scene_tables() {
  static const std::vector<TableSpec> tables = {
      {"scene", "what the scene is"},
      {"initial", "the one initial condition that feeds every model"},
      {"particles", "the event-driven gas (present = run it)"},
      {"continuum", "Burgers + continuity solvers (present = run them)"},
      {"compare", "the particle analysis, and particles against continuum (present with [continuum] = compare)"},
      {"sweep", "variants of the scene run side by side (present = sweep)"},
      {"output", "what is written besides result.h5 and summary.json"},
  };
  return tables;
}

std::string node_text(const toml::node& node) {
  std::ostringstream out;
  node.visit([&](const auto& n) { out << n; });
  return out.str();
}

}  // namespace shockgas::app
