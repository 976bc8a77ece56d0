#pragma once
// shockgas as a library: everything a program calls, in one include.
//
//   Bodies and the initial condition    shockgas/core/bodies.hpp, shockgas/core/initial_condition.hpp
//   the particle gas                    shockgas/particles/simulate.hpp (simulate, run_ensemble)
//   the exact sticky gas (r = 0)        shockgas/core/sticky_hull.hpp
//   the continuum solvers               shockgas/continuum/solve.hpp, shockgas/continuum/registry.hpp
//   particles against continuum         compare/*.hpp (theory.hpp: the laws)
//   scenes, as the command runs them    shockgas/app/scene/scene.hpp, shockgas/app/jobs/run_scene.hpp
//
// Parameters are plain structs with their defaults; each module declares its keys
// (unit, allowed values, doc) beside them (shockgas/core/parameters.hpp). Bad input throws
// InputError naming the key, a failed run RunError (shockgas/core/error.hpp).
#include "shockgas/app/jobs/run_scene.hpp"
#include "shockgas/app/scene/scene.hpp"
#include "shockgas/compare/cooling_law.hpp"
#include "shockgas/compare/deposit.hpp"
#include "shockgas/compare/matching.hpp"
#include "shockgas/compare/params.hpp"
#include "shockgas/compare/particle_analysis.hpp"
#include "shockgas/compare/sawtooth.hpp"
#include "shockgas/compare/shock_detection.hpp"
#include "shockgas/compare/snapshot_comparison.hpp"
#include "shockgas/compare/statistics.hpp"
#include "shockgas/compare/theory.hpp"
#include "shockgas/compare/velocity_distribution.hpp"
#include "shockgas/continuum/explicit_viscous.hpp"
#include "shockgas/continuum/field.hpp"
#include "shockgas/continuum/godunov.hpp"
#include "shockgas/continuum/hopf_cole.hpp"
#include "shockgas/continuum/hopf_lax.hpp"
#include "shockgas/continuum/params.hpp"
#include "shockgas/continuum/pressureless.hpp"
#include "shockgas/continuum/registry.hpp"
#include "shockgas/continuum/solve.hpp"
#include "shockgas/continuum/viscous_mol.hpp"
#include "shockgas/core/bodies.hpp"
#include "shockgas/core/error.hpp"
#include "shockgas/core/initial_condition.hpp"
#include "shockgas/core/parameters.hpp"
#include "shockgas/core/sticky_hull.hpp"
#include "shockgas/particles/cluster_finder.hpp"
#include "shockgas/particles/params.hpp"
#include "shockgas/particles/run_result.hpp"
#include "shockgas/particles/simulate.hpp"
#include "shockgas/version.hpp"

namespace shockgas {

// The version of the library the program runs with (kVersion: the one it was compiled against).
const char* library_version();

}  // namespace shockgas
