#pragma once
// The lab's initial conditions: five of the gallery's scenes
// (data/scenes/gallery/NAME.toml), each by the name of its file. The event
// engine, the hull and the Hopf-Lax solution start from them.
//
// The pointwise scenes' v0 and rho0 are written here in C++, not read from
// the scene's text, because the lab's WebAssembly build has no expression
// parser (muParser); tests/lab/test_lab_scenes.cpp holds each against its
// scene file through muParser, bit for bit (the n-wave's velocities to 1e-13:
// muParser's quotient is not always the correctly rounded one). White noise is the library's own
// draw (make_initial_bodies), as `shockgas run` draws realization 0.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "shockgas/core/bodies.hpp"
#include "shockgas/core/initial_condition.hpp"

namespace shockgas::lab {

struct LabScene {
  std::string name;    // the gallery file's stem, "sine"
  bool pointwise;      // v0, rho0 on the periodic [0, field.length) (velocities = "expression")
  InitialField field;  // pointwise scenes: length (the scene's domain), v0, rho0
};

// The scenes in the order the page lists them.
const std::vector<LabScene>& lab_scenes();
// The scene of that name; InputError naming "lab.scene" for another.
const LabScene& lab_scene(const std::string& name);

// The scene's [initial] table at N bodies and the seed (white noise: lattice
// positions, velocities uniform on [-1, 1], L = N; pointwise: the lattice of
// the expressions on [0, domain)). The key N as the scene files declare it.
InitialParams initial_params(const LabScene& scene, std::size_t N, std::uint64_t seed);

// Its bodies: make_initial_bodies for white noise, lattice_bodies of the field
// for the pointwise scenes (the same lattice, shockgas/core/initial_condition.hpp).
Bodies initial_bodies(const LabScene& scene, std::size_t N, std::uint64_t seed);

}  // namespace shockgas::lab
