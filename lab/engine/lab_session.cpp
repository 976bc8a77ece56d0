#include "lab/engine/lab_session.hpp"

#include <cmath>

#include "shockgas/continuum/hopf_lax.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::lab {

namespace {

// A whole number from the page, at least 0 and at most `most`.
std::uint64_t whole(double x, const std::string& key, double most, const std::string& why) {
  require(std::isfinite(x) && x >= 0 && x == std::floor(x), key, x, "a whole number >= 0");
  require(x <= most, key, x, "at most " + to_text(most) + why);
  return static_cast<std::uint64_t>(x);
}

std::size_t bodies_of(const LabSettings& s) {
  return whole(s.N, "initial.N", static_cast<double>(kMaxBodies),
               " in the lab (its memory, and frames at a rate to watch; larger runs: shockgas run)");
}

}  // namespace

particles::ParticleParams LabSession::params(const LabSettings& s) {
  particles::ParticleParams p;
  p.r = s.r;
  p.delta = s.delta;
  p.subthreshold = s.sticky ? particles::Subthreshold::sticky : particles::Subthreshold::elastic;
  p.geometry = s.line ? particles::Geometry::line : particles::Geometry::ring;
  particles::validate(p);  // r, delta: InputError naming the key
  return p;
}

LabSession::LabSession(const LabSettings& s)
    : settings_(s),
      scene_(lab_scene(s.scene)),
      initial_(initial_bodies(scene_, bodies_of(s), whole(s.seed, "initial.seed", 0x1p53, ""))),
      L_(domain_length(initial_params(scene_, initial_.size(), 0))),
      exact_data_(scene_.pointwise ? scene_.field : InitialField{L_, {}, {}, initial_, 0}),
      particle_mass_(initial_.m[0]),
      run_(initial_, L_, params(s)) {}

LabFrame LabSession::frame(std::size_t cells) const {
  LabFrame f;
  f.t = run_.time();
  f.bodies = run_.state();
  f.T = temperature(f.bodies);
  // The clusters of two or more particles, as the native run counts them.
  const double spacing = L_ / static_cast<double>(initial_.size());
  const particles::ClusterCriteria criteria =
      particles::gas_cluster_criteria(settings_.r, settings_.delta, spacing, f.t);
  const particles::MultiParticleRule counted(particle_mass_);
  for (const particles::Cluster& c : particles::find_clusters(f.bodies, ring() ? L_ : 0.0, criteria))
    if (counted.counts(c)) f.clusters.push_back(c);
  if (settings_.r == 0)
    f.hull = ring() ? sticky_clusters_ring(initial_, L_, f.t) : sticky_clusters_line(initial_, f.t);
  // The exact solution is that of the periodic problem: drawn on the ring only.
  if (ring()) f.exact = continuum::solve_hopf_lax(exact_data_, cells, f.t);
  return f;
}

}  // namespace shockgas::lab
