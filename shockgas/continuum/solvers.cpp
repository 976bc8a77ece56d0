// The built-in continuum solvers, in the order docs and plots list them. Each
// factory lives in its solver's own file; adding a solver adds one line here.
#include "shockgas/continuum/godunov.hpp"
#include "shockgas/continuum/hopf_cole.hpp"
#include "shockgas/continuum/hopf_lax.hpp"
#include "shockgas/continuum/pressureless.hpp"
#include "shockgas/continuum/registry.hpp"
#include "shockgas/continuum/viscous_mol.hpp"

namespace shockgas::continuum {

std::vector<SolverInfo> builtin_solvers() {
  return {
      godunov_solver(),       //
      godunov2_solver(),      //
      pressureless_solver(),  //
      hopf_lax_solver(),      //
      hopf_cole_solver(),     //
      cvode_solver(),         //
      arkode_solver(),        //
  };
}

}  // namespace shockgas::continuum
