#pragma once
// Scene table [continuum]: which solvers, at what resolution and viscosity.
#include <cstddef>
#include <string>
#include <vector>

namespace shockgas::continuum {

struct ContinuumParams {
  std::vector<std::string> solvers = {"hopf_lax", "godunov2"};  // from "godunov", "godunov2",
                                      // "pressureless", "hopf_lax", "hopf_cole", "cvode", "arkode"
  std::size_t cells = 4096;           // grid cells on the domain, >= 8
  double cfl = 0.5;                   // Courant number of the finite-volume schemes, (0, 1]
  double nu = 1e-3;                   // viscosity [length^2/time] for hopf_cole, cvode, arkode; > 0
  double t_end = 0.0;                 // final time [time]; 0 means particles.t_end, else > 0
  double rtol = 1e-6;                 // relative tolerance of cvode and arkode, in [1e-12, 1e-1]
  std::string hopf_cole_path = "auto";  // hopf_cole: "fft" (spectral heat equation), "log" (log-domain
                                      // heat kernel, any nu) or "auto" (fft unless its roundoff bound
                                      // exceeds rtol * max|v0|, then log; see hopf_cole.hpp)
  std::string limiter = "mc";         // slope limiter of godunov2: "minmod" | "vanleer" | "mc"
  std::string boundary = "periodic";  // "periodic" | "outflow"
  bool allow_unstable = false;        // run even outside a method's stable range (stability charts)
};

// Throws InputError naming the first key out of range (scheme-specific limits
// such as the CFL bound are checked by the solvers themselves).
void validate(const ContinuumParams& p);

}  // namespace shockgas::continuum
