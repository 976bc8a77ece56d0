#include "shockgas/particles/params.hpp"

#include <cmath>

#include "shockgas/core/error.hpp"

namespace shockgas::particles {

void validate(const ParticleParams& p) {
  require_in_range("particles.r", p.r, 0.0, 1.0);
  require(std::isfinite(p.delta) && p.delta >= 0, "particles.delta", p.delta, "a finite number >= 0");
  require(p.subthreshold == "elastic" || p.subthreshold == "sticky", "particles.subthreshold", p.subthreshold,
          "\"elastic\" or \"sticky\"");
  require(p.geometry == "ring" || p.geometry == "line", "particles.geometry", p.geometry,
          "\"ring\" or \"line\"");
  require(p.solver == "events" || p.solver == "hull", "particles.solver", p.solver, "\"events\" or \"hull\"");
  require(p.solver != "hull" || p.r == 0.0, "particles.solver", p.solver,
          "\"hull\" only with particles.r = 0 (the exact sticky solution)");
  require(p.schedule == "auto" || p.schedule == "windows" || p.schedule == "global", "particles.schedule",
          p.schedule, "\"auto\", \"windows\" or \"global\"");
  require_above("particles.t_end", p.t_end, 0.0);
  require(p.samples >= 1, "particles.samples", p.samples, "an integer >= 1");
  require(p.realizations >= 1, "particles.realizations", p.realizations, "an integer >= 1");
  for (double t : p.snapshots)
    require(std::isfinite(t) && t >= 0 && t <= p.t_end, "particles.snapshots", t,
            "times in [0, particles.t_end]");
  require_above("particles.histogram_zmax", p.histogram_zmax, 0.0);
  require(p.spacetime_frames >= 2, "particles.spacetime_frames", p.spacetime_frames, "an integer >= 2");
  require(std::isfinite(p.max_wall_seconds) && p.max_wall_seconds >= 0, "particles.max_wall_seconds",
          p.max_wall_seconds, "a finite number of seconds >= 0 (0 = no limit)");
}

}  // namespace shockgas::particles
