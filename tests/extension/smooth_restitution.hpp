#pragma once
// A restitution law written outside shockgas, as docs/design.md §5 ("A collision
// rule") shows: the restitution of an inelastic collision falls smoothly from 1
// for slow impacts to particles.r for fast ones,
//
//     r(g) = r + (1 - r) exp(-g / g0),
//
// with its own speed scale g0, fixed here when the law is registered (a law of
// the library declares it as a scene key). g0 = 0 is the constant r to the bit:
// exp(-g / 0) = exp(-inf) = 0 for every g > 0, and r + (1 - r) 0 = r.
#include <cmath>
#include <string>

#include "shockgas/core/error.hpp"
#include "shockgas/particles/restitution_laws.hpp"

namespace shockgas::extension {

inline double smooth_restitution(double r, double g0, double g) { return r + (1.0 - r) * std::exp(-g / g0); }

// The law as registered under `name`, with speed scale g0 [length/time].
inline particles::RestitutionLawInfo smooth_restitution_law(std::string name, double g0) {
  particles::RestitutionLawInfo law;
  law.name = std::move(name);
  law.summary = "r(g) = r + (1 - r) exp(-g / g0), g0 = " + to_text(g0);
  law.make = [g0](const particles::ParticleParams& p) -> particles::RestitutionLaw {
    return [r = p.r, g0](double g) { return smooth_restitution(r, g0, g); };
  };
  return law;
}

}  // namespace shockgas::extension
