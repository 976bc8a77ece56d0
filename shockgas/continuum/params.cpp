// The declarations of scene table [continuum] and the rules between its keys.
#include "shockgas/continuum/params.hpp"

#include "shockgas/continuum/registry.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::continuum {

namespace {

ParameterTable<ContinuumParams> declare() {
  using P = ContinuumParams;
  ParameterTable<P> t("continuum");
  t.add(&P::solvers, "solvers", "", "continuum solvers to run", one_of(solver_names));
  t.add(&P::cells, "cells", "1", "grid cells on the domain", allowed(at_least(8)));
  t.add(
      &P::cfl, "cfl", "1", "Courant number of the finite-volume schemes",
      Allowed{above(0), {}, "a Courant number in (0, 1] (set continuum.allow_unstable = true to go beyond)"});
  t.add(&P::nu, "nu", "length^2/time",
        "viscosity of the viscous solvers (those with uses nu in the solver table of docs/scenes.md)",
        allowed(above(0)));
  t.add(&P::t_end, "t_end", "time", "final time; 0 = particles.t_end", allowed(at_least(0)));
  t.add(&P::rtol, "rtol", "1", "relative tolerance of the adaptive integrators",
        allowed(between(1e-12, 0.1)));
  t.add(&P::hopf_cole_path, "hopf_cole_path", "",
        "Hopf-Cole evaluation: spectral heat equation, log-domain heat kernel, or chosen by its roundoff "
        "bound");
  t.add(&P::limiter, "limiter", "", "slope limiter of the second-order finite-volume scheme");
  t.add(
      &P::boundary, "boundary", "",
      "boundary condition; outflow (zero-gradient) only for the finite-volume solvers, the others solve the "
      "periodic problem and refuse it");
  t.add(&P::allow_unstable, "allow_unstable", "",
        "run even outside a method's stable range (for stability studies)");
  t.add(&P::threads, "threads", "1",
        "threads of the finite-volume solvers (godunov, godunov2, pressureless), the grid cut into as many "
        "segments of at least 4096 cells: the same cells for any number; 0 = all usable cores",
        allowed(at_least(0)));
  return t;
}

}  // namespace

// The registered solvers marked by_default, the exact one first.
std::vector<std::string> ContinuumParams::default_solver_names() {
  std::vector<std::string> names;
  for (const auto& s : registered_solvers())
    if (s.by_default && s.exact) names.push_back(s.name);
  for (const auto& s : registered_solvers())
    if (s.by_default && !s.exact) names.push_back(s.name);
  return names;
}

const ParameterTable<ContinuumParams>& parameters() {
  static const ParameterTable<ContinuumParams> table = declare();
  return table;
}

void validate(const ContinuumParams& p) {
  parameters().check(p);
  require(!p.solvers.empty(), "continuum.solvers", std::string("[]"), "at least one registered solver");
  for (std::size_t i = 0; i < p.solvers.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      require(p.solvers[i] != p.solvers[j], "continuum.solvers", p.solvers[i],
              "each solver once (it writes one group of results)");
  require(p.cfl <= 1 || p.allow_unstable, "continuum.cfl", p.cfl,
          "a Courant number in (0, 1] (set continuum.allow_unstable = true to go beyond)");
}

}  // namespace shockgas::continuum
