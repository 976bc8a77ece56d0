// The solver registry (registry.hpp): the built-in solvers, then any a program adds.
#include "shockgas/continuum/registry.hpp"

#include "shockgas/core/error.hpp"

namespace shockgas::continuum {

std::vector<SolverInfo> builtin_solvers();  // shockgas/continuum/solvers.cpp

namespace {

std::vector<SolverInfo>& registry() {
  static std::vector<SolverInfo> solvers = builtin_solvers();
  return solvers;
}

}  // namespace

void register_solver(SolverInfo info) {
  require(!info.name.empty(), "continuum.solvers", info.name, "a solver with a name");
  require(info.preflight && info.run, "continuum.solvers", info.name,
          "a solver with a preflight and a run function");
  for (const auto& s : registry())
    require(s.name != info.name, "continuum.solvers", info.name, "a name not yet registered");
  registry().push_back(std::move(info));
}

const std::vector<SolverInfo>& registered_solvers() { return registry(); }

std::vector<std::string> solver_names() {
  std::vector<std::string> names;
  for (const auto& s : registry()) names.push_back(s.name);
  return names;
}

const SolverInfo& solver_info(const std::string& name) {
  for (const auto& s : registry())
    if (s.name == name) return s;
  throw InputError("continuum.solvers", to_text(name), "one of " + choices_text(solver_names()));
}

std::string reference_solver_name() {
  for (const auto& s : registry())
    if (s.exact) return s.name;
  return "";
}

void check_boundary(const SolverInfo& info, const ContinuumParams& p) {
  if (p.boundary != Boundary::outflow || info.outflow) return;
  std::vector<std::string> with_outflow;
  for (const auto& s : registry())
    if (s.outflow) with_outflow.push_back(s.name);
  throw InputError("continuum.boundary", "\"outflow\"",
                   "\"periodic\" for solver " + info.name +
                       ", which solves the periodic problem only (outflow: " + choices_text(with_outflow) +
                       ")");
}

void preflight(const std::string& name, const InitialField& f, const ContinuumParams& p, double t_end) {
  const SolverInfo& info = solver_info(name);
  check_boundary(info, p);
  info.preflight(f, p, t_end);
}

}  // namespace shockgas::continuum
