// Observables measured in parts over stretches of the chain and combined in
// chain order (stretch_observables.hpp), against the whole chain: the cluster
// count of ClusterCounter and of find_clusters on the sorted copy filtered by
// MultiParticleRule to the bit wherever the chain is in order (however it is
// cut: the seam, the closing pair and lone bodies inside a stretch or at a
// cut), and of the stably sorted copy where rounding left it out of order
// inside a stretch; the temperature to rounding.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>

#include "chain_fixtures.hpp"
#include "shockgas/particles/chain_observables.hpp"
#include "shockgas/particles/ring_wrap.hpp"
#include "shockgas/particles/stretch_observables.hpp"

namespace shockgas::particles::detail {
namespace {

using namespace testing;

// The part of bodies order[lo] .. order[hi - 1] of the chain, as a domain measures it.
StretchPart part_of(const Chain& c, const std::vector<std::size_t>& order, std::size_t lo, std::size_t hi,
                    const SampleSpec& spec, std::optional<ClusterPart>& sorted) {
  StretchPart p;
  ClusterScan scan(spec);
  std::vector<ScanBody> wv;
  for (std::size_t k = lo; k < hi; ++k) {
    const std::size_t b = order[k];
    const double w = spec.ring ? ref_wrap(c.x[b], c.L) : c.x[b];
    p.mass += c.m[b], p.momentum += c.m[b] * c.v[b], ++p.bodies;
    scan.add(w, c.v[b], c.m[b], c.first[b], k > lo && c.first[b] < c.first[order[k - 1]]);
    wv.push_back({w, c.v[b], c.m[b]});
  }
  for (std::size_t k = lo; k < hi; ++k) {
    const double dv = c.v[order[k]] - p.momentum / p.mass;
    p.spread += c.m[order[k]] * dv * dv;
  }
  p.clusters = scan.part();
  if (out_of_order(p.clusters, spec))
    sorted = sorted_part(wv, p.clusters.first_index, p.clusters.last_index, spec);
  return p;
}

struct Combined {
  SampleMoments moments;
  ClusterCount streamed;   // from the parts as streamed
  std::size_t clusters{};  // with sorted parts where a stretch was out of order
};

// The chain cut into `stretches` runs from body `start` on (ring: wrapping past
// the last body), never right of body `keep` (a pair that must stay inside).
Combined combine(const Chain& c, bool ring, const ClusterCriteria& criteria, std::size_t start,
                 std::size_t stretches, std::size_t keep, Rng& rng) {
  const std::size_t n = c.x.size();
  std::vector<std::size_t> order(n);
  for (std::size_t k = 0; k < n; ++k) order[k] = (start + k) % n;
  std::vector<std::size_t> cuts{0, n};
  while (cuts.size() < stretches + 1 && n > stretches) {
    const std::size_t k = 1 + static_cast<std::size_t>(static_cast<double>(n - 1) * rng.uniform());
    if (order[k - 1] != keep && std::find(cuts.begin(), cuts.end(), k) == cuts.end()) cuts.push_back(k);
  }
  std::sort(cuts.begin(), cuts.end());
  const SampleSpec spec{true, criteria, MultiParticleRule(mean_particle_mass(c)), c.L, ring};
  std::vector<StretchPart> parts;
  std::vector<std::optional<ClusterPart>> sorted;
  for (std::size_t s = 0; s + 1 < cuts.size(); ++s) {
    sorted.emplace_back();
    parts.push_back(part_of(c, order, cuts[s], cuts[s + 1], spec, sorted.back()));
  }
  Combined out;
  out.moments = combine_moments(parts.data(), parts.size(), 1);
  std::vector<const ClusterPart*> as_streamed, with_sorted;
  for (std::size_t s = 0; s < parts.size(); ++s) {
    as_streamed.push_back(&parts[s].clusters);
    with_sorted.push_back(sorted[s] ? &*sorted[s] : &parts[s].clusters);
  }
  out.streamed = count_clusters(as_streamed, out.moments.bodies, spec);
  out.clusters = out.streamed.ordered ? out.streamed.count : count_clusters(with_sorted, n, spec).count;
  return out;
}

std::optional<std::size_t> streamed_count(const Chain& c, bool ring, const ClusterCriteria& criteria) {
  ClusterCounter counter(c.L, ring, criteria, MultiParticleRule(mean_particle_mass(c)));
  view_of(c).visit([&](const ChainChunk& chunk) { counter.add(chunk); }, Fields::all);
  return counter.count();
}

// Rounding of two orders of the same sums: a sum of n terms errs by at most
// (n + 4) eps times the sum of their magnitudes (Higham, Accuracy and Stability,
// 4.2), so the two orders differ by twice that; a mean off by d adds M d^2 to
// sum m (v - mean)^2 (the first-order term vanishes at the mean).
void expect_same_moments(const Chain& c, const SampleMoments& m) {
  const auto [mean, T] = ref_mean_and_temperature(c);
  const double eps = std::numeric_limits<double>::epsilon();
  const double n = static_cast<double>(c.x.size());
  double mass = 0, momentum_scale = 0;
  for (std::size_t b = 0; b < c.x.size(); ++b) mass += c.m[b], momentum_scale += c.m[b] * std::abs(c.v[b]);
  EXPECT_EQ(m.bodies, c.x.size());
  EXPECT_NEAR(m.mass, mass, 2 * (n + 4) * eps * mass);
  EXPECT_NEAR(m.momentum / m.mass, mean, 2 * (n + 4) * eps * momentum_scale / mass);
  const double d = 2 * (n + 4) * eps * momentum_scale / mass;
  EXPECT_NEAR(m.T, T, 2 * (n + 4) * eps * T + 2 * d * d);
}

// wrap_all takes one period for a whole run of positions: each result must be
// wrap_into's to the bit, for runs inside one period, across a boundary, at
// exact multiples of L and far from the first period.
TEST(PeriodWrap, WrapAllEqualsWrapIntoToTheBit) {
  Rng rng(43);
  for (double L : {1.0, 3000.0, 1e7, 0.1 * 3}) {
    PeriodWrap wrap(L);
    std::vector<double> x(257), w(257);
    for (int run = 0; run < 2000; ++run) {
      const std::size_t n = 1 + static_cast<std::size_t>(256 * rng.uniform());
      const double k = std::floor(rng.uniform(run % 7 == 0 ? -3000.0 : -3.0, 3.0));
      double at = (k + rng.uniform()) * L;
      for (std::size_t i = 0; i < n; ++i) {
        const double u = rng.uniform();
        at += rng.uniform(0.0, u < 0.9 ? 1e-3 : 0.2) * L;
        x[i] = u < 0.95 ? at : std::nextafter(std::round(at / L) * L, u < 0.975 ? -1e300 : 1e300);
      }
      wrap.wrap_all(x.data(), w.data(), n);
      for (std::size_t i = 0; i < n; ++i) {
        const double want = wrap_into(x[i], L);
        ASSERT_EQ(std::bit_cast<std::uint64_t>(w[i]), std::bit_cast<std::uint64_t>(want))
            << "x = " << x[i] << ", L = " << L;
      }
    }
  }
}

TEST(StretchObservables, OrderedChainsCountAsTheWholeChainHoweverCut) {
  Rng rng(41);
  std::size_t whole_rings = 0;
  for (std::size_t bodies : {2u, 3u, 17u, 300u, 2500u}) {
    for (int trial = 0; trial < 30; ++trial) {
      for (bool ring : {true, false}) {
        SCOPED_TRACE(std::to_string(bodies) + (ring ? " ring " : " line ") + std::to_string(trial));
        const Chain c = random_chain(rng, bodies, 0.02, ring);
        const ClusterCriteria criteria = trial % 3 == 0 ? ClusterCriteria{rng.uniform(0.0, 4.0), 0.3}
                                                        : default_cluster_criteria(0.02, 1.0);
        const std::optional<std::size_t> whole = streamed_count(c, ring, criteria);
        ASSERT_TRUE(whole.has_value());
        const std::size_t start = ring ? static_cast<std::size_t>(bodies * rng.uniform()) : 0;
        const std::size_t stretches = 1 + static_cast<std::size_t>(8 * rng.uniform());
        const Combined got = combine(c, ring, criteria, start, stretches, bodies, rng);
        EXPECT_TRUE(got.streamed.ordered);
        EXPECT_EQ(got.clusters, *whole);
        EXPECT_EQ(got.clusters, ref_counted(c, ring, criteria, MultiParticleRule(mean_particle_mass(c))));
        expect_same_moments(c, got.moments);
        whole_rings += ring && *whole == 1;
      }
    }
  }
  EXPECT_GT(whole_rings, 0u);  // the fully joined ring was exercised
}

// A rounding-sized drop inside a stretch (as in ChainObservables.Misordered...):
// the stretch's sorted part stands in, and the count is the sorted copy's.
TEST(StretchObservables, MisorderedStretchesCountAsTheSortedCopy) {
  Rng rng(42);
  std::size_t refused = 0;
  for (bool ring : {true, false}) {
    for (int trial = 0; trial < 40; ++trial) {
      SCOPED_TRACE(std::string(ring ? "ring" : "line") + ", trial " + std::to_string(trial));
      Chain c = random_chain(rng, 300, 0.02, ring);
      const std::size_t left = misorder(c, ring && trial % 2 == 1, rng);
      const ClusterCriteria criteria = default_cluster_criteria(0.02, 1.0);
      const std::size_t expected = ref_counted(c, ring, criteria, MultiParticleRule(mean_particle_mass(c)));
      std::size_t start = ring ? static_cast<std::size_t>(300 * rng.uniform()) : 0;
      if (ring && start == (left + 1) % 300) start = left;  // the drop not at the ring's closing cut
      const Combined got = combine(c, ring, criteria, start, 5, left, rng);
      refused += !streamed_count(c, ring, criteria).has_value();
      EXPECT_EQ(got.clusters, expected);
      expect_same_moments(c, got.moments);
    }
  }
  EXPECT_GT(refused, 20u);  // most chains were out of order for the whole-chain counter
}

// Every body at one place on a ring (all in one collision): no pair drops, so
// the pair that closes the chain order (body n - 1, body 0) is the wrapping one
// (gap L): inside a stretch (even trials: the chain cut from another body on,
// never right of n - 1) or at the ring's last cut (odd: from body 0 on). It
// joins under criteria wider than the ring.
TEST(StretchObservables, BodiesAtOnePlaceCloseTheRingAcrossTheWrap) {
  Rng rng(44);
  for (int trial = 0; trial < 200; ++trial) {
    SCOPED_TRACE("trial " + std::to_string(trial));
    Chain c = random_chain(rng, 2 + static_cast<std::size_t>(trial % 9), 0.02, true);
    for (double& x : c.x) x = c.x.front();
    const std::size_t n = c.x.size();
    const ClusterCriteria criteria{trial % 3 == 0 ? 2 * c.L : 0.5, 0.1};
    const bool inside = trial % 2 == 0;
    const std::size_t start =
        inside ? 1 + static_cast<std::size_t>(static_cast<double>(n - 1) * rng.uniform()) : 0;
    const std::size_t stretches = 1 + static_cast<std::size_t>(trial % 4);
    const Combined got = combine(c, true, criteria, start, stretches, inside ? n - 1 : n, rng);
    EXPECT_TRUE(got.streamed.ordered);
    EXPECT_EQ(got.clusters, streamed_count(c, true, criteria));
    EXPECT_EQ(got.clusters, ref_counted(c, true, criteria, MultiParticleRule(mean_particle_mass(c))));
  }
}

}  // namespace
}  // namespace shockgas::particles::detail
