#pragma once
// The continuum solvers, each registered once: its name (as continuum.solvers
// spells it), what it needs and produces, how plots draw it, its own limits
// (checked before any work, without solving) and the function that runs it.
// Dispatch (solve.hpp), the allowed names of continuum.solvers, the preflight of
// a run, the L1 reference and the plots' labels and colours all read this.
//
// Adding a solver: write it in its own files, give it a SolverInfo factory there,
// and add one line to the list in shockgas/continuum/solvers.cpp (docs/design.md §5 shows a
// worked example). A program may also register_solver() its own at start-up.
#include <functional>
#include <string>
#include <vector>

#include "shockgas/continuum/field.hpp"
#include "shockgas/continuum/params.hpp"
#include "shockgas/core/initial_condition.hpp"
#include "shockgas/core/progress.hpp"

namespace shockgas::continuum {

struct SolverInfo {
  std::string name;         // as continuum.solvers spells it; unique
  std::string summary;      // one line: the method
  std::string label;        // legend text of the plots
  std::string colour;       // plot colour, a matplotlib colour ("tab:blue", "#1f77b4", "black")
  bool density = false;     // returns rho, the cell averages of the density
  bool shocks = false;      // returns its own shock list (ContinuumResult::has_shocks)
  bool viscous = false;     // solves at viscosity continuum.nu
  bool exact = false;       // the exact inviscid solution: the others' L1 errors are measured against it
  bool by_default = false;  // run when a scene does not name continuum.solvers
  bool outflow = false;     // solves with continuum.boundary = "outflow" too (else the periodic problem only)
  // Memory at work per cell, bytes (the run's resource preflight); 0 = not
  // measured, taken as the largest of the registered solvers'.
  double bytes_per_cell = 0;
  // Memory at work per initial body, bytes, when it solves from point masses
  // (InitialField::from_bodies); 0 for a solver that uses the cell averages alone.
  double bytes_per_body = 0;
  // Evaluates its fields at any t directly (closed form in t, no marching): the
  // fields at several times are one evaluation each. A solver without it marches,
  // and continues from its own cell averages at each output time (series.hpp).
  bool direct_in_time = false;
  // Its own limits for these data, parameters and end time (CFL bound, cells
  // against nu, ...), checked without solving; InputError naming the key.
  std::function<void(const InitialField&, const ContinuumParams&, double t_end)> preflight;
  // The solve from f to t_end (InputError, RunError as its header says).
  std::function<ContinuumResult(const InitialField&, const ContinuumParams&, double t_end,
                                const ProgressCallback&)>
      run;
};

// Adds a solver after the built-in ones. Register at start-up, before any run
// (the registry is not locked). InputError if the name is empty or taken, or
// preflight or run is missing.
void register_solver(SolverInfo info);

// Every registered solver: the built-in ones (shockgas/continuum/solvers.cpp) first.
const std::vector<SolverInfo>& registered_solvers();
std::vector<std::string> solver_names();

// The solver called `name`; InputError naming continuum.solvers and listing the names if none.
const SolverInfo& solver_info(const std::string& name);

// InputError "continuum.boundary" where p asks for a boundary the solver does
// not solve with (SolverInfo::outflow): it would solve another problem.
void check_boundary(const SolverInfo& info, const ContinuumParams& p);

// The name of the exact solver (the reference of L1 errors and of the comparison).
std::string reference_solver_name();

// Checks solver `name`'s own limits for f, p and t_end, without solving, and
// that it solves for p.boundary (InputError "continuum.boundary" otherwise).
void preflight(const std::string& name, const InitialField& f, const ContinuumParams& p, double t_end);

}  // namespace shockgas::continuum
