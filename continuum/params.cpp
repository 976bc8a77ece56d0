#include "shockgas/continuum/params.hpp"

#include <algorithm>
#include <cmath>

#include "shockgas/core/error.hpp"

namespace shockgas::continuum {

namespace {
constexpr const char* kSolvers[] = {"godunov", "godunov2", "pressureless", "hopf_lax",
                                    "hopf_cole", "cvode", "arkode"};
}

void validate(const ContinuumParams& p) {
  for (const auto& s : p.solvers)
    require(std::find(std::begin(kSolvers), std::end(kSolvers), s) != std::end(kSolvers),
            "continuum.solvers", s,
            "a list from \"godunov\", \"godunov2\", \"pressureless\", \"hopf_lax\", \"hopf_cole\", "
            "\"cvode\", \"arkode\"");
  require(p.cells >= 8, "continuum.cells", p.cells, "an integer >= 8");
  require(std::isfinite(p.cfl) && p.cfl > 0 && (p.cfl <= 1 || p.allow_unstable), "continuum.cfl", p.cfl,
          "a Courant number in (0, 1] (set continuum.allow_unstable = true to go beyond)");
  require_above("continuum.nu", p.nu, 0.0);
  require(std::isfinite(p.t_end) && p.t_end >= 0, "continuum.t_end", p.t_end,
          "a finite time > 0, or 0 for particles.t_end");
  require_in_range("continuum.rtol", p.rtol, 1e-12, 1e-1);
  require(p.limiter == "minmod" || p.limiter == "vanleer" || p.limiter == "mc", "continuum.limiter",
          p.limiter, "\"minmod\", \"vanleer\" or \"mc\"");
  require(p.hopf_cole_path == "auto" || p.hopf_cole_path == "fft" || p.hopf_cole_path == "log",
          "continuum.hopf_cole_path", p.hopf_cole_path, "\"auto\", \"fft\" or \"log\"");
  require(p.boundary == "periodic" || p.boundary == "outflow", "continuum.boundary", p.boundary,
          "\"periodic\" or \"outflow\"");
}

}  // namespace shockgas::continuum
