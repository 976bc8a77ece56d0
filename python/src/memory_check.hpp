#pragma once
// The command's memory preflight (app/resources.hpp) for the module's calls
// that take their parameters as keywords rather than as a scene: a call that
// cannot fit is an InputError naming the key that needs most, before any work,
// not the kernel's out-of-memory killer ending the Python process.
#include <cstddef>

#include "resources.hpp"

namespace shockgas::python {

// A scene of N bodies with these particle and continuum parameters (either
// may be absent), checked as `shockgas run` checks one.
inline void check_memory_of(std::size_t N, const particles::ParticleParams* particles,
                            const continuum::ContinuumParams* continuum) {
  app::Scene s;
  s.initial.N = N;
  if (particles) s.has_particles = true, s.particles = *particles;
  if (continuum) s.has_continuum = true, s.continuum = *continuum;
  app::check_memory(s);
}

}  // namespace shockgas::python
