#pragma once
// Chains as a model holds them (chain_view.hpp), the recorder's previous code
// on a copy of them as the reference, and random chains with the features the
// observables must handle. Shared by the tests of the streamed observables.
#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>
#include <vector>

#include "shockgas/core/bodies.hpp"
#include "shockgas/core/random.hpp"
#include "shockgas/particles/chain_view.hpp"
#include "shockgas/particles/cluster_finder.hpp"

namespace shockgas::particles::detail::testing {

// A state in chain order, as a model holds it (see chain_view.hpp).
struct Chain {
  std::vector<std::size_t> first;
  std::vector<double> x, v, m;
  std::size_t particles = 0;
  double L = 0;
};

inline auto view_of(const Chain& c) {
  return make_chain_view(c.x.size(), [&c](auto&& f, std::size_t begin, std::size_t end) {
    for (std::size_t b = begin; b < end; ++b) f(c.first[b], c.x[b], c.v[b], c.m[b]);
  });
}

// ---- The reference: the recorder's previous code, on a copy of the chain. ----

inline double ref_wrap(double x, double L) {
  double w = x - L * std::floor(x / L);
  return w >= L || w < 0 ? 0.0 : w;
}

inline Bodies ref_sorted(const Chain& s, bool ring) {
  const std::size_t n = s.x.size();
  std::vector<double> x = s.x;
  std::size_t start = 0;
  if (ring) {
    for (double& xi : x) xi = ref_wrap(xi, s.L);
    for (std::size_t b = 1; b < n; ++b)
      if (x[b] < x[b - 1]) {
        start = b;
        break;
      }
  }
  std::vector<std::size_t> order(n);
  for (std::size_t k = 0; k < n; ++k) order[k] = (start + k) % n;
  auto by_x = [&](std::size_t a, std::size_t b) { return x[a] < x[b]; };
  if (!std::is_sorted(order.begin(), order.end(), by_x)) std::stable_sort(order.begin(), order.end(), by_x);
  Bodies out;
  for (std::size_t k : order) out.push_back(x[k], s.v[k], s.m[k]);
  return out;
}

// M / N of the chain's particles: what the run's MultiParticleRule takes.
inline double mean_particle_mass(const Chain& s) {
  return std::accumulate(s.m.begin(), s.m.end(), 0.0) / static_cast<double>(s.particles);
}

// The clusters of the sorted copy (find_clusters) that the rule counts.
inline std::size_t ref_counted(const Chain& s, bool ring, const ClusterCriteria& criteria,
                               const MultiParticleRule& rule) {
  const std::vector<Cluster> clusters = find_clusters(ref_sorted(s, ring), ring ? s.L : 0.0, criteria);
  return static_cast<std::size_t>(
      std::count_if(clusters.begin(), clusters.end(), [&](const Cluster& k) { return rule.counts(k); }));
}

inline std::pair<double, double> ref_mean_and_temperature(const Chain& s) {
  double mass = 0, momentum = 0;
  for (std::size_t b = 0; b < s.v.size(); ++b) mass += s.m[b], momentum += s.m[b] * s.v[b];
  const double mean = momentum / mass;
  double T = 0;
  for (std::size_t b = 0; b < s.v.size(); ++b) T += s.m[b] * (s.v[b] - mean) * (s.v[b] - mean);
  return {mean, T / mass};
}

// A random chain with the features the observables must handle: merged bodies
// (gaps in `first`), runs of close co-moving neighbours (clusters), gaps and
// velocity differences at the criteria's limits, equal positions, a ring closed
// by a close pair or a wide one, and (ring) positions unrolled by whole periods,
// so that the wrapped chain has a seam. L = particles (mean spacing 1): the
// default criteria at delta join neighbours closer than 1/2 whose velocities
// differ by less than 5 delta.
inline Chain random_chain(Rng& rng, std::size_t bodies, double delta, bool ring) {
  Chain c;
  std::size_t next = ring ? static_cast<std::size_t>(3 * rng.uniform()) : 0;
  std::vector<double> gap(bodies, 0.0);
  double v = 0;
  for (std::size_t b = 0; b < bodies; ++b) {
    const double u = rng.uniform();
    if (b > 0)
      gap[b] = u < 0.05 ? 0.0 : u < 0.1 ? 0.5 : u < 0.5 ? rng.uniform(0.0, 0.6) : rng.uniform(0.6, 3.0);
    const double w = rng.uniform();
    v = w < 0.05 ? v + 5 * delta : w < 0.7 ? v + rng.uniform(-6 * delta, 6 * delta) : rng.uniform(-1.0, 1.0);
    c.first.push_back(next);
    c.v.push_back(v);
    c.m.push_back(rng.uniform() < 0.8 ? 1.0 : rng.uniform(0.5, 3.0));
    next += rng.uniform() < 0.9 ? 1 : 2 + static_cast<std::size_t>(3 * rng.uniform());
  }
  // The ring closes at L = particles with a gap close (and co-moving) half the
  // time: one inner gap takes up the rest of the period.
  const bool close = rng.uniform() < 0.5;
  const double closing = close ? rng.uniform(0.0, 0.6) : rng.uniform(0.6, 3.0);
  if (close && bodies > 1) c.v.back() = c.v.front() + rng.uniform(-6 * delta, 6 * delta);
  const double span = std::accumulate(gap.begin(), gap.end(), 0.0);
  c.particles = std::max(next, static_cast<std::size_t>(std::ceil(span + closing)));
  c.L = static_cast<double>(c.particles);
  if (bodies > 1)
    gap[1 + static_cast<std::size_t>(static_cast<double>(bodies - 1) * rng.uniform())] +=
        c.L - closing - span;
  // Whole periods, and a fraction of one (none: the seam is at the chain's start).
  const double fraction = rng.uniform() < 0.2 ? 0.0 : rng.uniform(0.0, c.L);
  const double offset = ring ? std::floor(rng.uniform(-3.0, 3.0)) * c.L + fraction : rng.uniform(-5.0, 5.0);
  double x = offset;
  for (std::size_t b = 0; b < bodies; ++b) c.x.push_back(x += gap[b]);
  return c;
}

// A rounding-sized drop of the positions (as rounding leaves touching bodies):
// body k put just left of its left neighbour, with its velocity; across: k = 0
// against the last body (ring), else a random body inside. Returns the left one.
inline std::size_t misorder(Chain& c, bool across, Rng& rng) {
  const std::size_t n = c.x.size();
  const std::size_t k = across ? 0 : 1 + static_cast<std::size_t>(static_cast<double>(n - 2) * rng.uniform());
  const std::size_t left = across ? n - 1 : k - 1;
  c.x[k] = c.x[left] - (across ? c.L : 0.0) - 1e-9 * c.L;
  c.v[k] = c.v[left];
  return left;
}

}  // namespace shockgas::particles::detail::testing
