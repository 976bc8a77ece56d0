#pragma once
// The one initial condition that feeds every model (DESIGN.md §3): the particles
// see it as point masses, the continuum as pointwise data or cell averages.
#include <cstdint>
#include <functional>
#include <string>

#include "shockgas/core/bodies.hpp"

namespace shockgas {

// Scene table [initial].
struct InitialParams {
  std::size_t N = 10000;               // number of particles [1], N >= 2
  std::string positions = "lattice";   // "lattice" (equal spacing) | "random" (uniform, sorted)
  std::string velocities = "uniform";  // "uniform" on [-amplitude, amplitude] | "gaussian"
                                       // (sd amplitude) | "file" | "expression" (v0)
  double amplitude = 1.0;              // velocity scale [length/time], > 0
  bool remove_mean = false;            // subtract the mean velocity (zero total momentum)
  std::string file;                    // text file, columns `x v [m]`, sorted by x
  std::uint64_t seed = 1;              // random seed; realization k uses realization_seed(seed, k)
  double L = 0.0;                      // ring length / line extent [length]; 0 means L = N
  std::string v0 = "0.5 + sin(2*pi*x)";  // v0(x) for velocities = "expression" [length/time]
  std::string rho0 = "1";                // rho0(x) for velocities = "expression" [mass/length]
  double domain = 1.0;                   // period of v0, rho0: the domain is [0, domain) [length]
};

// Pointwise initial data on [0, length): what the continuum solvers discretise.
struct InitialField {
  double length = 1.0;                  // domain length [length]
  std::function<double(double)> v0;     // velocity v0(x), if given pointwise
  std::function<double(double)> rho0;   // density rho0(x), if given pointwise
  Bodies bodies;                        // point masses, if the data are particles
  bool from_bodies() const { return !v0; }
};

// Domain length of the scene: domain for expressions, else L (or N if L = 0).
double domain_length(const InitialParams& p);

// The particles of realization `realization` (positions in [0, length)).
// For velocities = "expression" the N particles sit on a lattice with masses
// rho0(x) * length / N and velocities v0(x).
Bodies make_initial_bodies(const InitialParams& p, std::uint64_t realization = 0);

// The continuum's view of realization `realization`: the expressions when
// velocities = "expression", else the particles as point masses.
InitialField make_initial_field(const InitialParams& p, std::uint64_t realization = 0);

// Checks every key of p (throws InputError naming the key); called by the scene
// parser and by anyone building InitialParams in code.
void validate(const InitialParams& p);

}  // namespace shockgas
