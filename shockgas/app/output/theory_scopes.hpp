#pragma once
// The laws of shockgas/compare/theory_scope.hpp applied to a run: the scene's
// shape as their conditions read it, the time each law is held at (the
// particles' end, the comparison's time, the last frame), and the summary keys
// theory.<id> that say, for every law, whether it holds for the run and on
// which window (plots and report.md state a law only where it holds).
#include <string>
#include <vector>

#include "shockgas/app/scene/scene.hpp"
#include "shockgas/compare/theory_scope.hpp"
#include "shockgas/core/initial_condition.hpp"

namespace shockgas::app {

struct RunResults;

// The shape of a scene's start (its realization 0 and the continuum's view of it).
compare::SceneShape scene_shape(const Scene& scene, const InitialCondition& initial);

// When the data a law is held against end: particles.t_end for the particles'
// laws, the continuum's t_end for the comparison's, the last frame for a wave's.
double law_time(const Scene& scene, compare::Law law);

// The law's scope and its report text for this run (compare::scope, theory_note),
// held to the time its data end: law_time, or the particles' stop where they
// stopped before particles.t_end.
compare::Scope law_scope(const RunResults& r, compare::Law law);
std::string law_note(const RunResults& r, compare::Law law);

}  // namespace shockgas::app
