#pragma once
// The restitution laws of the inelastic collisions, each registered once: its
// name (as particles.restitution_law spells it), what it is, and how it makes
// r(g) from the scene's [particles] table (collision.hpp, RestitutionLaw). The
// built-in one, particles.r for every g, makes no function at all: the engine
// then keeps its constant rule, and its time windows.
//
// Adding a law: write it in its own header with a RestitutionLawInfo factory,
// declare its own parameters, if any, in ParticleParams (params.hpp, params.cpp),
// and add one line to the list in shockgas/particles/restitution_laws.cpp
// (docs/design.md §5, "A collision rule"). A program may also
// register_restitution_law() its own at start-up.
#include <functional>
#include <string>
#include <vector>

#include "shockgas/particles/collision.hpp"
#include "shockgas/particles/params.hpp"

namespace shockgas::particles {

struct RestitutionLawInfo {
  std::string name;     // as particles.restitution_law spells it; unique
  std::string summary;  // one line: r(g), and which keys it reads
  // r(g) for these parameters (r > 0), in (0, 1] for every g >= delta; an empty
  // function for the constant particles.r.
  std::function<RestitutionLaw(const ParticleParams&)> make;
};

// Adds a law after the built-in ones. Register at start-up, before any run (the
// registry is not locked). InputError if the name is empty or taken, or make is
// missing.
void register_restitution_law(RestitutionLawInfo info);

// Every registered law: the built-in ones (restitution_laws.cpp) first.
const std::vector<RestitutionLawInfo>& registered_restitution_laws();
std::vector<std::string> restitution_law_names();

// The law called `name`; InputError naming particles.restitution_law and listing the names if none.
const RestitutionLawInfo& restitution_law_info(const std::string& name);

// The law of p.restitution_law for p, empty for the constant r. A registered
// law's r(g) outside (0, 1] stops the run: RunError naming the law, g and r(g).
RestitutionLaw restitution_law(const ParticleParams& p);

}  // namespace shockgas::particles
