#include "lab/engine/lab_scenes.hpp"

#include <cmath>
#include <numbers>

#include "shockgas/core/error.hpp"

namespace shockgas::lab {

namespace {

constexpr double pi = std::numbers::pi;

// A pointwise scene: v0 and rho0 as in data/scenes/gallery/NAME.toml, whose
// text each line repeats; the scenes' domain is 1.
LabScene pointwise(std::string name, double (*v0)(double), double (*rho0)(double)) {
  LabScene s{std::move(name), true, {}};
  s.field.length = 1.0;
  s.field.v0 = v0;
  s.field.rho0 = rho0;
  return s;
}

double uniform_density(double) { return 1; }  // rho0 = "1"

// sine.toml: v0 = "0.5 + sin(2*pi*x)"
double sine(double x) { return 0.5 + std::sin(2 * pi * x); }

// riemann.toml: v0 = "(x < 0.3) ? -0.5 : ((x < 0.6) ? 0.25 : ((x < 0.8) ? 1 : -0.5))"
double riemann(double x) { return (x < 0.3) ? -0.5 : ((x < 0.6) ? 0.25 : ((x < 0.8) ? 1 : -0.5)); }

// n-wave.toml: v0 = "(abs(x - 0.5) < 0.025) ? -sin(2*pi*(x - 0.475)/0.05) : 0"
double n_wave(double x) { return (std::abs(x - 0.5) < 0.025) ? -std::sin(2 * pi * (x - 0.475) / 0.05) : 0; }

// merging-shocks.toml: v0 = "(x >= 0.1 && x < 0.4) ? 1 : ((x >= 0.6 && x < 0.9) ? -0.5 : 0)"
double merging(double x) { return (x >= 0.1 && x < 0.4) ? 1 : ((x >= 0.6 && x < 0.9) ? -0.5 : 0); }

}  // namespace

const std::vector<LabScene>& lab_scenes() {
  static const std::vector<LabScene> scenes = {
      LabScene{"cooling", false, {}},  // white noise: [initial] N, seed only
      pointwise("sine", sine, uniform_density),
      pointwise("riemann", riemann, uniform_density),
      pointwise("n-wave", n_wave, uniform_density),
      pointwise("merging-shocks", merging, uniform_density),
  };
  return scenes;
}

const LabScene& lab_scene(const std::string& name) {
  std::string names;
  for (const LabScene& s : lab_scenes()) {
    if (s.name == name) return s;
    names += (names.empty() ? "" : ", ") + s.name;
  }
  throw InputError("lab.scene", "\"" + name + "\"", "one of " + names);
}

InitialParams initial_params(const LabScene& scene, std::size_t N, std::uint64_t seed) {
  InitialParams p;
  p.N = N;
  p.seed = seed;
  if (scene.pointwise) {
    p.velocities = Velocities::expression;
    p.domain = scene.field.length;
  }
  return p;
}

Bodies initial_bodies(const LabScene& scene, std::size_t N, std::uint64_t seed) {
  const InitialParams p = initial_params(scene, N, seed);
  initial_parameters().check(p);  // N >= 2, as a scene file says it
  return scene.pointwise ? lattice_bodies(scene.field, N) : make_initial_bodies(p, 0);
}

}  // namespace shockgas::lab
