#pragma once
// The one initial condition that feeds every model (docs/design.md §3): the
// particles see it as point masses, the continuum as pointwise data or cell
// averages.
#include <array>
#include <cstdint>
#include <functional>
#include <string>

#include "shockgas/core/bodies.hpp"
#include "shockgas/core/parameters.hpp"

namespace shockgas {

enum class Positions { lattice, random };
constexpr std::array<EnumName<Positions>, 2> enum_names(Positions) {
  return {{{Positions::lattice, "lattice"}, {Positions::random, "random"}}};
}

enum class Velocities { uniform, gaussian, file, expression };
constexpr std::array<EnumName<Velocities>, 4> enum_names(Velocities) {
  return {{{Velocities::uniform, "uniform"},
           {Velocities::gaussian, "gaussian"},
           {Velocities::file, "file"},
           {Velocities::expression, "expression"}}};
}

// Scene table [initial]. Unit, allowed range and meaning of every member are
// declared once in initial_parameters() (shockgas/core/initial_condition.cpp).
struct InitialParams {
  std::size_t N = 10000;
  Positions positions = Positions::lattice;
  Velocities velocities = Velocities::uniform;
  double amplitude = 1.0;
  bool remove_mean = false;
  std::string file;
  std::uint64_t seed = 1;  // realization k uses realization_seed(seed, k)
  double L = 0.0;          // 0 means L = N
  std::string v0 = "0.5 + sin(2*pi*x)";
  std::string rho0 = "1";
  double domain = 1.0;
};

// The declarations of [initial]: key, unit, allowed values, doc.
const ParameterTable<InitialParams>& initial_parameters();

// Pointwise initial data on [0, length): what the continuum solvers discretise.
struct InitialField {
  double length = 1.0;                 // domain length [length]
  std::function<double(double)> v0;    // velocity v0(x), if given pointwise
  std::function<double(double)> rho0;  // density rho0(x), if given pointwise
  Bodies bodies;                       // point masses, if the data are particles
  std::size_t pieces = 0;              // if > 0: v0 and rho0 are constant on each of `pieces`
                                       // equal cells of [0, length) (data given as cell values)
  bool from_bodies() const { return !v0; }
};

// The ring's length for N bodies: L, or N (mean spacing 1) where L = 0. The one
// rule of initial.L, for scenes, simulate(bodies, L, ...) and the Python module.
double ring_length(double L, std::size_t N);

// Domain length of the scene: domain for expressions, else ring_length(L, N).
double domain_length(const InitialParams& p);

// The particles of realization `realization` (positions in [0, length)).
// For velocities = "expression" the N particles sit on a lattice with masses
// rho0(x) * length / N and velocities v0(x).
Bodies make_initial_bodies(const InitialParams& p, std::uint64_t realization = 0);

// N bodies on the lattice of pointwise data f (f.v0 and f.rho0 given, L =
// f.length): positions x_i = (i + 1/2) L / N, velocities v0(x_i), masses
// rho0(x_i) L / N. What make_initial_bodies gives for velocities = "expression"
// (before remove_mean), and the lab's scenes (lab/engine/lab_scenes.hpp).
Bodies lattice_bodies(const InitialField& f, std::size_t N);

// The continuum's view of realization `realization`: the expressions when
// velocities = "expression", else the particles as point masses.
InitialField make_initial_field(const InitialParams& p, std::uint64_t realization = 0);

// The initial condition of a scene, built once and handed to every model: the
// particles of realization 0 and the continuum's view of the same data. Other
// realizations are drawn on demand (their seeds depend on their index only).
class InitialCondition {
 public:
  // What it keeps of realization 0's particles: the bodies, or (Keep::stream,
  // where they can be drawn on the fly: InitialStream::streamable) nothing,
  // every reader drawing them in chunks (stream_realization) instead of a
  // whole copy of 24 bytes per particle.
  enum class Keep { bodies, stream };

  // Validates p (InputError naming the key) and builds realization 0.
  explicit InitialCondition(const InitialParams& p, Keep keep = Keep::bodies);

  const InitialParams& params() const { return params_; }
  double length() const { return field_.length; }
  // Realization 0 as point masses (for expressions: the lattice of N bodies of
  // make_initial_bodies). Sorted, positions in [0, length). RunError when they
  // are not held (holds_bodies()).
  const Bodies& bodies() const;
  // Whether bodies() holds realization 0; if not, field().bodies is empty too.
  bool holds_bodies() const { return held_; }
  // Realization k >= 1 (k = 0: a copy of bodies()). Data from a file or from
  // expressions do not depend on k. To read one without a whole copy:
  // stream_realization (shockgas/core/initial_stream.hpp).
  Bodies realization(std::uint64_t k) const;
  // Whether realizations differ (random velocities), or all equal bodies().
  bool depends_on_realization() const;
  // The continuum's view of realization 0: expressions, or bodies() as point masses.
  const InitialField& field() const { return field_; }

 private:
  InitialParams params_;
  InitialField field_;
  Bodies expression_bodies_;
  bool held_ = true;
};

// Checks every key of p (throws InputError naming the key): the declared rules,
// then the rules between keys (the file exists for velocities = "file", the
// expressions parse and are finite, rho0 > 0). Called by the scene parser and by
// anyone building InitialParams in code.
void validate(const InitialParams& p);

}  // namespace shockgas
