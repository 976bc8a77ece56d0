#pragma once
// What solve_cvode and solve_arkode share on their SUNDIALS integrator: its options
// and the march to t_end. Private to shockgas_continuum (it includes SUNDIALS).
#include "shockgas/continuum/sundials_wrap.hpp"
#include "shockgas/continuum/viscous_mol_setup.hpp"
#include "shockgas/core/progress.hpp"

namespace shockgas::continuum {

// The problem's tolerances and stop time t_end, the preconditioner's half_bandwidth,
// and the Krylov dimension and step limit between output times of both solvers.
sundials::Options mol_integrator_options(const MolProblem& m, long half_bandwidth);

// Integrates from m.y0 at t = 0 to m.t_end > 0 through the output times t_end k / kMolOutputs,
// k = 1..kMolOutputs: at each, require_finite_state and progress(k / kMolOutputs, t).
// The result at t_end with the integrator's statistics; the caller adds the note.
ContinuumResult march_mol(const MolProblem& m, sundials::Integrator& integrator,
                          const ProgressCallback& progress);

}  // namespace shockgas::continuum
