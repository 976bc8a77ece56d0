#pragma once
// Scene table [continuum]: which solvers, at what resolution and viscosity.
#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "shockgas/core/parameters.hpp"

namespace shockgas::continuum {

// Slope limiter of the second-order finite-volume scheme (limiters.hpp).
enum class Limiter { minmod, vanleer, mc };
constexpr std::array<EnumName<Limiter>, 3> enum_names(Limiter) {
  return {{{Limiter::minmod, "minmod"}, {Limiter::vanleer, "vanleer"}, {Limiter::mc, "mc"}}};
}

// Boundary of the finite-volume grid: periodic, or outflow (zero-gradient ghost cells).
enum class Boundary { periodic, outflow };
constexpr std::array<EnumName<Boundary>, 2> enum_names(Boundary) {
  return {{{Boundary::periodic, "periodic"}, {Boundary::outflow, "outflow"}}};
}

// How Hopf-Cole evaluates ln theta (hopf_cole.hpp): spectral heat equation,
// log-domain heat kernel, or automatic = fft unless its roundoff bound exceeds
// rtol * max|v0|.
enum class HopfColePath { automatic, fft, log };
constexpr std::array<EnumName<HopfColePath>, 3> enum_names(HopfColePath) {
  return {{{HopfColePath::automatic, "auto"}, {HopfColePath::fft, "fft"}, {HopfColePath::log, "log"}}};
}

// Unit, allowed range and meaning of every member: parameters() (shockgas/continuum/params.cpp).
struct ContinuumParams {
  std::vector<std::string> solvers = default_solver_names();  // registered names (registry.hpp)
  std::size_t cells = 4096;
  double cfl = 0.5;  // beyond a scheme's own bound only with allow_unstable
  double nu = 1e-3;
  double t_end = 0.0;  // 0 means particles.t_end
  double rtol = 1e-6;
  HopfColePath hopf_cole_path = HopfColePath::automatic;
  Limiter limiter = Limiter::mc;
  Boundary boundary = Boundary::periodic;
  bool allow_unstable = false;
  std::size_t threads = 0;  // finite-volume solvers; 0 = all usable cores

  // The registered solvers that a scene runs unless it names others.
  static std::vector<std::string> default_solver_names();
};

// The declarations of [continuum]: key, unit, allowed values, doc.
const ParameterTable<ContinuumParams>& parameters();

// Throws InputError naming the first key out of range: the declared rules, then
// cfl <= 1 unless allow_unstable. A solver's own limits (its CFL bound, cells
// against nu, ...) are checked by its preflight (registry.hpp).
void validate(const ContinuumParams& p);

}  // namespace shockgas::continuum
