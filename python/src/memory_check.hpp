#pragma once
// The command's memory preflight (shockgas/app/run/resources.hpp) for the module's calls
// that take their parameters as keywords rather than as a scene: a call that
// cannot fit is an InputError naming the key that needs most, before any work,
// not the kernel's out-of-memory killer ending the Python process.
#include <cstddef>
#include <string>

#include "shockgas/app/run/resources.hpp"
#include "shockgas/core/error.hpp"

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

// A call that holds `bytes` at its peak (`what` they are), set by `key` =
// value: refused as the command refuses a scene that cannot fit.
inline void check_bytes(double bytes, const std::string& what, const std::string& key, double value) {
  app::ResourceEstimate e;
  e.items.push_back({key, what, bytes});
  app::require_memory(e, "a call",
                      [&](const std::string& allowed) { return InputError(key, to_text(value), allowed); });
}

}  // namespace shockgas::python
