// The observables streamed over the chain against the path they replace, kept
// here as the reference: copy the state, wrap it, rotate and sort it
// (sorted_bodies), run find_clusters on the copy (the clusters MultiParticleRule
// counts) and sum over the copy. Equal to the bit: same sums in the same order,
// same cluster criteria and rule on the same numbers.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <numeric>

#include "chain_fixtures.hpp"
#include "shockgas/core/initial_condition.hpp"
#include "shockgas/core/random.hpp"
#include "shockgas/particles/chain_observables.hpp"
#include "shockgas/particles/recorder.hpp"
#include "shockgas/particles/simulate.hpp"
#include "shockgas/particles/sorted_state.hpp"

namespace shockgas::particles::detail {
namespace {

using namespace testing;

std::vector<double> ref_histogram(const Chain& s, double t, std::size_t bins, double zmax) {
  const double dz = 2 * zmax / static_cast<double>(bins);
  const auto [mean, T] = ref_mean_and_temperature(s);
  const double mass = std::accumulate(s.m.begin(), s.m.end(), 0.0);
  const double scale = std::cbrt(t);
  std::vector<double> row(bins, 0.0);
  for (std::size_t b = 0; b < s.v.size(); ++b) {
    const double bin = std::floor(((s.v[b] - mean) * scale + zmax) / dz);
    if (bin >= 0 && bin < static_cast<double>(bins))
      row[static_cast<std::size_t>(bin)] += s.m[b] / (mass * dz);
  }
  return row;
}

std::vector<double> ref_frame(const Chain& s, bool ring) {
  auto wrap = [&](double x) { return ring ? ref_wrap(x, s.L) : x; };
  std::vector<double> row(s.particles);
  const std::size_t bodies = s.x.size();
  for (std::size_t b = 0; b < bodies; ++b) {
    const std::size_t end = b + 1 < bodies ? s.first[b + 1] : s.particles;
    for (std::size_t k = s.first[b]; k < end; ++k) row[k] = wrap(s.x[b]);
  }
  for (std::size_t k = 0; k < s.first.front(); ++k) row[k] = wrap(s.x.back());
  return row;
}

// ---- Streamed against the reference. ----

ParticleParams record_everything(double delta) {
  ParticleParams p;
  p.r = 0.5;
  p.delta = delta;
  p.t_end = 100.0;
  p.samples = 3;
  p.histogram_bins = 24;
  p.histogram_zmax = 3.0;
  p.snapshots = {10.0};
  p.spacetime = true;
  p.spacetime_frames = 2;
  p.spacetime_particles = std::numeric_limits<std::size_t>::max();  // every world line, as ref_frame
  return p;
}

// The recorder fed the same state at every stop.
RunResult record(const Chain& s, const ParticleParams& p, bool ring) {
  Recorder recorder(p, s.particles, s.L, ring, mean_particle_mass(s));
  for (double t = recorder.next_stop(); t != Recorder::done; t = recorder.next_stop())
    recorder.observe(t, view_of(s), Counters{});
  return recorder.finish(view_of(s), RunStop{}, Counters{});
}

// A record of 7 world lines holds the reference frame's columns at its labels.
void expect_world_lines_of_labels(const Chain& s, ParticleParams p, bool ring,
                                  const std::vector<double>& frame) {
  p.spacetime_particles = 7;
  const SpaceTime st = record(s, p, ring).spacetime;
  ASSERT_EQ(st.labels, spacetime_labels(s.particles, 7));
  ASSERT_EQ(st.x.size(), 2 * st.labels.size());
  for (std::size_t j = 0; j < st.labels.size(); ++j)
    EXPECT_EQ(st.x[st.labels.size() + j], frame[st.labels[j]]);
}

void expect_bodies_equal(const Bodies& a, const Bodies& b) {
  EXPECT_EQ(a.x, b.x);
  EXPECT_EQ(a.v, b.v);
  EXPECT_EQ(a.m, b.m);
}

void expect_matches_reference(const Chain& s, const ParticleParams& p, bool ring) {
  const RunResult out = record(s, p, ring);
  // The criteria at the sample's time.
  auto criteria = [&](double t) {
    return p.r == 0 ? merged_bodies_criteria()  // every collision merges (collision.hpp)
                    : default_cluster_criteria(p.delta, s.L / static_cast<double>(s.particles), t);
  };
  const Bodies sorted = ref_sorted(s, ring);
  const auto [mean, T] = ref_mean_and_temperature(s);
  const MultiParticleRule rule(mean_particle_mass(s));
  ASSERT_EQ(out.series.size(), p.samples);
  for (std::size_t k = 0; k < p.samples; ++k) {
    EXPECT_EQ(out.series.T[k], T);
    EXPECT_EQ(out.series.mean_v[k], mean);
    EXPECT_EQ(out.series.n_bodies[k], static_cast<double>(s.x.size()));
    EXPECT_EQ(out.series.n_clusters[k],
              static_cast<double>(ref_counted(s, ring, criteria(out.series.t[k]), rule)));
    const std::vector<double> row = ref_histogram(s, out.histogram.t[k], p.histogram_bins, p.histogram_zmax);
    EXPECT_TRUE(std::equal(row.begin(), row.end(), out.histogram.density.begin() + k * p.histogram_bins));
  }
  ASSERT_EQ(out.snapshots.size(), 1u);
  expect_bodies_equal(out.snapshots[0].bodies, sorted);
  expect_bodies_equal(out.final_state, sorted);
  const std::vector<double> frame = ref_frame(s, ring);
  ASSERT_EQ(out.spacetime.x.size(), 2 * s.particles);
  EXPECT_TRUE(std::equal(frame.begin(), frame.end(), out.spacetime.x.begin() + s.particles));
  expect_world_lines_of_labels(s, p, ring, frame);
}

TEST(ChainObservables, RandomRingChainsEqualTheSortedCopy) {
  Rng rng(21);
  for (std::size_t bodies : {1u, 2u, 3u, 17u, 1000u, 2500u}) {
    for (int trial = 0; trial < 20; ++trial) {
      SCOPED_TRACE("bodies " + std::to_string(bodies) + ", trial " + std::to_string(trial));
      expect_matches_reference(random_chain(rng, bodies, 0.02, true), record_everything(0.02), true);
    }
  }
}

TEST(ChainObservables, RandomLineChainsEqualTheSortedCopy) {
  Rng rng(22);
  const ParticleParams p = record_everything(0.02);
  for (std::size_t bodies : {1u, 2u, 17u, 2500u}) {
    for (int trial = 0; trial < 20; ++trial) {
      SCOPED_TRACE("bodies " + std::to_string(bodies) + ", trial " + std::to_string(trial));
      expect_matches_reference(random_chain(rng, bodies, 0.02, false), p, false);
    }
  }
}

// PeriodWrap skips the division while x stays in one period: its result must be
// wrap_into's to the bit, at period boundaries and far from the first period too.
TEST(PeriodWrap, EqualsWrapIntoToTheBit) {
  Rng rng(28);
  for (double L : {1.0, 3000.0, 1e7, 0.1 * 3}) {
    PeriodWrap wrap(L);
    double x = -5 * L;
    for (int i = 0; i < 200000; ++i) {
      const double u = rng.uniform();
      // Mostly small steps (a chain), some jumps, some exact multiples of L and their neighbours.
      const double k = std::floor(rng.uniform(-2000.0, 2000.0));
      x = u < 0.8    ? x + rng.uniform(-0.01, 0.05) * L
          : u < 0.9  ? rng.uniform(-1e6, 1e6) * L
          : u < 0.95 ? k * L
                     : std::nextafter(k * L, u < 0.975 ? -1e300 : 1e300);
      const double got = wrap(x), want = wrap_into(x, L);
      ASSERT_EQ(std::bit_cast<std::uint64_t>(got), std::bit_cast<std::uint64_t>(want))
          << "x = " << x << ", L = " << L;
    }
  }
}

// The counter alone, under criteria wide enough to join a whole ring, and a
// rule under which none, some or all bodies are heavy (masses 0.5 .. 3, or 1).
TEST(ClusterCounter, EqualsFindClustersOnTheSortedCopy) {
  Rng rng(27);
  std::size_t whole_rings = 0, lone = 0, heavy_lone = 0;
  for (std::size_t bodies : {1u, 2u, 3u, 5u, 40u}) {
    for (int trial = 0; trial < 50; ++trial) {
      for (bool ring : {true, false}) {
        const Chain c = random_chain(rng, bodies, 0.02, ring);
        const ClusterCriteria criteria{rng.uniform(0.0, 4.0), rng.uniform(0.0, 0.3)};
        const MultiParticleRule rule(trial % 5 == 0 ? 0.3 : rng.uniform(0.2, 2.5));
        ClusterCounter counter(c.L, ring, criteria, rule);
        view_of(c).visit([&](const ChainChunk& chunk) { counter.add(chunk); }, Fields::all);
        const std::vector<Cluster> all = find_clusters(ref_sorted(c, ring), ring ? c.L : 0.0, criteria);
        ASSERT_TRUE(counter.count().has_value());
        EXPECT_EQ(*counter.count(), ref_counted(c, ring, criteria, rule));
        whole_rings += ring && bodies > 1 && all.size() == 1;
        for (const Cluster& k : all) lone += k.count == 1, heavy_lone += k.count == 1 && rule.heavy(k.m);
      }
    }
  }
  EXPECT_GT(whole_rings, 0u);          // the fully joined ring was exercised
  EXPECT_GT(lone - heavy_lone, 100u);  // lone light bodies were left out
  EXPECT_GT(heavy_lone, 100u);         // ... and lone heavy ones counted
}

// Rounding can leave two touching bodies out of order in x (a second drop of the
// wrapped positions): the streamed count refuses, and the recorder counts on the
// sorted copy, as before.
TEST(ChainObservables, MisorderedChainsFallBackToTheSortedCopy) {
  Rng rng(23);
  for (bool ring : {true, false}) {
    const ParticleParams p = record_everything(0.02);
    for (int trial = 0; trial < 20; ++trial) {
      SCOPED_TRACE(std::string(ring ? "ring" : "line") + ", trial " + std::to_string(trial));
      Chain c = random_chain(rng, 300, 0.02, ring);
      // A rounding-sized drop inside the chain, or (ring) across its ends.
      const bool across = ring && trial % 2 == 1;
      const std::size_t left = misorder(c, across, rng);
      const std::size_t k = across ? 0 : left + 1;
      ClusterCounter counter(c.L, ring, default_cluster_criteria(0.02, 1.0), MultiParticleRule(1.0));
      view_of(c).visit([&](const ChainChunk& chunk) { counter.add(chunk); }, Fields::all);
      if (!ring || ref_wrap(c.x[k], c.L) < ref_wrap(c.x[left], c.L)) {
        EXPECT_FALSE(counter.count().has_value());
      }
      expect_matches_reference(c, p, ring);
    }
  }
}

// The state read in chunks (what a StateSink gets) as the bodies of a read;
// the last body it tells without a read (StateReader::last), where it does,
// is the read's last, bit for bit.
Bodies read_whole(const StateReader& state) {
  Bodies b;
  state.read([&](const double* x, const double* v, const double* m, std::size_t count) {
    for (std::size_t i = 0; i < count; ++i) b.push_back(x[i], v[i], m[i]);
  });
  if (const auto last = state.last()) {
    EXPECT_FALSE(b.size() == 0);
    if (b.size() > 0) {
      EXPECT_EQ(*last, (std::array<double, 3>{b.x.back(), b.v.back(), b.m.back()}));
    }
  }
  return b;
}

// Misordered chains read through SortedState (the order window, no copy), and
// sorted_bodies (the window in place), in the sorted copy's order, bit for bit.
TEST(SortedState, MisorderedChainsReadAsTheSortedCopy) {
  Rng rng(27);
  for (bool ring : {true, false})
    for (int trial = 0; trial < 20; ++trial) {
      SCOPED_TRACE(std::string(ring ? "ring" : "line") + ", trial " + std::to_string(trial));
      Chain c = random_chain(rng, 3000, 0.02, ring);
      misorder(c, ring && trial % 2 == 1, rng);
      expect_bodies_equal(read_whole(SortedState(view_of(c), c.L, ring)), ref_sorted(c, ring));
      expect_bodies_equal(sorted_bodies(view_of(c), c.L, ring), ref_sorted(c, ring));  // ordered in place
    }
}

// A body far behind its place (more than the window of 4096): read and
// sorted through a stable sort of a copy, in the same order.
TEST(SortedState, ABodyFarOutOfPlaceReadsAsTheSortedCopy) {
  Rng rng(28);
  for (bool ring : {true, false}) {
    SCOPED_TRACE(ring ? "ring" : "line");
    Chain c = random_chain(rng, 20000, 0.02, ring);
    c.x[15000] = c.x[10] + 1e-9 * c.L;  // behind 14990 bodies
    const auto view = view_of(c);       // outlives the state, which reads it
    const SortedState state(view, c.L, ring);
    EXPECT_TRUE(state.through_copy());
    expect_bodies_equal(read_whole(state), ref_sorted(c, ring));
    expect_bodies_equal(sorted_bodies(view_of(c), c.L, ring), ref_sorted(c, ring));
  }
}

// n unit bodies on a ring of length n, one per unit cell from start * n on
// (unrolled: the chain crosses the period after (1 - start) n bodies), at a
// random place in the first half of its cell; velocities in [-1, 1].
Chain ring_chain_from(Rng& rng, std::size_t n, double start) {
  Chain c;
  c.L = static_cast<double>(n), c.particles = n;
  for (std::size_t b = 0; b < n; ++b) {
    c.first.push_back(b);
    c.x.push_back(start * c.L + static_cast<double>(b) + rng.uniform(0.0, 0.5));
    c.v.push_back(rng.uniform(-1.0, 1.0));
    c.m.push_back(1.0);
  }
  return c;
}

// A state read through SortedState without a sorted copy, and read and sorted
// (sorted_bodies) in the sorted copy's order, bit for bit.
void expect_read_without_a_copy(const Chain& c) {
  const auto view = view_of(c);  // outlives the state, which reads it
  const SortedState state(view, c.L, true);
  EXPECT_FALSE(state.through_copy());
  expect_bodies_equal(read_whole(state), ref_sorted(c, true));
  expect_bodies_equal(sorted_bodies(view, c.L, true), ref_sorted(c, true));
}

// The bodies before the seam are held back while the rest is read when they are
// few (up to 2^16), and read in a second pass when they are many: both in the
// sorted copy's order, bit for bit, in order from the seam and misordered.
TEST(SortedState, ManyOrFewBodiesBeforeTheSeamReadAsTheSortedCopy) {
  Rng rng(29);
  for (const double start : {0.999, 0.6}) {  // about 200 and 80000 bodies before the seam
    for (const bool misordered : {false, true}) {
      SCOPED_TRACE("start " + std::to_string(start) + (misordered ? ", misordered" : ""));
      Chain c = ring_chain_from(rng, 200000, start);
      if (misordered) c.x[150000] = std::nextafter(c.x[149999], 0.0);  // a rounding-sized drop
      const auto view = view_of(c);                                    // outlives the state, which reads it
      const SortedState state(view, c.L, true);
      EXPECT_EQ(state.last().has_value(), !misordered);  // known where the order from the seam is sorted
      expect_bodies_equal(read_whole(state), ref_sorted(c, true));
    }
  }
}

// A rounding-sized drop before the ring's seam (touching bodies out of order,
// anywhere in a long run at large N) is not the seam: the state is read in the
// sorted copy's order through the window, without a copy, on either side of the
// seam and with both.
TEST(SortedState, ARoundingDropBeforeTheSeamIsNotTheSeam) {
  Rng rng(30);
  const std::size_t n = 200000, seam = 80000;  // the chain starts at 0.6 L
  for (const std::vector<std::size_t>& drops :
       std::vector<std::vector<std::size_t>>{{100}, {79999}, {100, 150000}, {150000}}) {
    SCOPED_TRACE("drops at " + std::to_string(drops.front()) +
                 (drops.size() > 1 ? " and after the seam" : ""));
    Chain c = ring_chain_from(rng, n, 0.6);
    for (std::size_t k : drops) c.x[k] = std::nextafter(c.x[k - 1], 0.0);
    ASSERT_LT(c.x[seam] - c.L, c.x[seam - 1]);  // wrapped, the positions drop at the seam
    expect_read_without_a_copy(c);
  }
}

// Without a crossing of the ring's period the chain's start is the seam, also
// when rounding left a drop: read through the window, without a copy.
TEST(SortedState, ARoundingDropWithoutACrossingKeepsTheStart) {
  Rng rng(31);
  Chain c = ring_chain_from(rng, 20000, 0.0);
  c.x[5000] = std::nextafter(c.x[4999], 0.0);
  expect_read_without_a_copy(c);
}

// Merging gas (r = 0, delta = 0): every body is its own cluster, counted when
// heavier than 1.5 M / N (a merged body of unit masses; the chain's masses
// are 1 or 0.5 .. 3).
TEST(ChainObservables, MergedBodiesAreCountedWhenHeavy) {
  Rng rng(24);
  ParticleParams p = record_everything(0.0);
  p.r = 0.0;
  const Chain c = random_chain(rng, 2000, 0.02, true);
  expect_matches_reference(c, p, true);
  const double heavy = 1.5 * mean_particle_mass(c);
  const double counted =
      static_cast<double>(std::count_if(c.m.begin(), c.m.end(), [&](double m) { return m > heavy; }));
  EXPECT_GT(counted, 0.0);
  EXPECT_LT(counted, 2000.0);
  EXPECT_EQ(record(c, p, true).series.n_clusters.back(), counted);
}

// Real states: the engine's snapshots (sorted, wrapped) turned back into chains,
// cut at a random body and unrolled by whole periods, as the engine holds them.
TEST(ChainObservables, EngineStatesEqualTheSortedCopy) {
  InitialParams ip;
  ip.N = 3000;
  ip.seed = 25;
  Rng rng(26);
  for (const Subthreshold subthreshold : {Subthreshold::elastic, Subthreshold::sticky}) {
    ParticleParams run;
    run.r = 0.5;
    run.subthreshold = subthreshold;
    run.t_end = 300.0;
    run.snapshots = {10.0, 100.0, 300.0};
    const RunResult out = simulate(make_initial_bodies(ip), 3000.0, run);
    for (const Snapshot& snap : out.snapshots) {
      SCOPED_TRACE(std::string(subthreshold == Subthreshold::sticky ? "sticky" : "elastic") +
                   ", t = " + std::to_string(snap.t));
      const Bodies& b = snap.bodies;
      const std::size_t n = b.size();
      const std::size_t cut = static_cast<std::size_t>(static_cast<double>(n) * rng.uniform());
      const double periods = std::floor(rng.uniform(-3.0, 3.0)) * 3000.0;
      Chain c;
      c.L = 3000.0;
      for (std::size_t k = 0; k < n; ++k) {
        const std::size_t i = (cut + k) % n;
        c.first.push_back(c.particles);
        c.x.push_back(b.x[i] + (cut + k >= n ? c.L : 0.0) + periods);
        c.v.push_back(b.v[i]);
        c.m.push_back(b.m[i]);
        c.particles += static_cast<std::size_t>(b.m[i]);  // unit masses merge into integer ones
      }
      expect_matches_reference(c, record_everything(run.delta), true);
    }
  }
}

}  // namespace
}  // namespace shockgas::particles::detail
