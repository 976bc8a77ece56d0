// The frame times of an animation and the rules of its keys (frames.hpp).
#include "shockgas/app/output/frames.hpp"

#include <algorithm>
#include <cmath>

#include "shockgas/core/error.hpp"

namespace shockgas::app {

namespace {

constexpr double kMaxRecordedBodies = 1e7;  // bodies x frames: 240 MB of x, v, m

double end_time(const Scene& scene) {
  return scene.has_particles ? scene.particles.t_end : scene.continuum_t_end();
}

double log_start(const Scene& scene) {
  const auto& o = scene.output;
  return o.animation_t_min > 0 ? o.animation_t_min : end_time(scene) / 1000;
}

}  // namespace

std::vector<double> frame_times(const Scene& scene) {
  const std::size_t n = scene.output.animation_frames;
  const double t_end = end_time(scene);
  std::vector<double> t(n, 0.0);
  if (scene.output.animation_spacing == FrameSpacing::linear) {
    for (std::size_t k = 1; k < n; ++k) t[k] = t_end * static_cast<double>(k) / static_cast<double>(n - 1);
  } else {
    const double t0 = log_start(scene);
    for (std::size_t k = 1; k < n; ++k)
      t[k] = t0 * std::pow(t_end / t0, static_cast<double>(k - 1) / static_cast<double>(n > 2 ? n - 2 : 1));
  }
  t.back() = t_end;
  return t;
}

particles::ParticleParams particle_params(const Scene& scene) {
  particles::ParticleParams params = scene.particles;
  if (!scene.output.animation) return params;
  const std::vector<double> frames = frame_times(scene);
  auto& t = params.snapshots;
  t.insert(t.end(), frames.begin(), frames.end());
  std::sort(t.begin(), t.end());
  t.erase(std::unique(t.begin(), t.end()), t.end());
  return params;
}

void check_animation(const Scene& scene) {
  const auto& o = scene.output;
  if (!o.animation) return;
  require(scene.has_particles || scene.has_continuum, "output.animation", std::string("true"),
          "false for a scene without [particles] or [continuum] (nothing moves)");
  if (o.animation_spacing == FrameSpacing::log)
    require(log_start(scene) < end_time(scene), "output.animation_t_min", o.animation_t_min,
            "a time before the run's end (" + to_text(end_time(scene)) + ")");
  if (scene.has_particles) {
    const double bodies = static_cast<double>(scene.initial.N) * static_cast<double>(o.animation_frames);
    require(bodies <= kMaxRecordedBodies, "output.animation_frames", o.animation_frames,
            "at most " + to_text(std::floor(kMaxRecordedBodies / static_cast<double>(scene.initial.N))) +
                " frames for N = " + std::to_string(scene.initial.N) + " (each frame stores every body)");
  }
}

}  // namespace shockgas::app
