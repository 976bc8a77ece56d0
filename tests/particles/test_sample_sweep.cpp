// The one-pass sweep of a run of equal-mass bodies (sample_sweep.hpp) against
// the general path it replaces: positions at t into a buffer, wrap_all, add_run,
// and the velocity sums in four lanes; and add_run's pairs two at a time
// against add() body by body. Equal to the bit: the lane sums, every field of
// the cluster part, the lone bodies too (also after runs that went the general
// way), on rings (near and across period boundaries, far periods) and lines,
// with bodies at several local times and rounding-sized drops, light and heavy.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "shockgas/core/random.hpp"
#include "shockgas/particles/sample_sweep.hpp"

#if defined(__SSE2__)

namespace shockgas::particles::detail {
namespace {

struct Body {
  double x, v, t;
  double at(double s) const { return x + v * (s - t); }
};

bool same_bits(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

void expect_same_part(const ClusterPart& a, const ClusterPart& b) {
  EXPECT_EQ(a.joined, b.joined);
  EXPECT_EQ(a.drops, b.drops);
  EXPECT_TRUE(same_bits(a.max_drop, b.max_drop));
  EXPECT_EQ(a.closing_counted, b.closing_counted);
  EXPECT_EQ(a.closing_wrapped, b.closing_wrapped);
  EXPECT_TRUE(same_bits(a.first_w, b.first_w));
  EXPECT_TRUE(same_bits(a.first_v, b.first_v));
  EXPECT_TRUE(same_bits(a.last_w, b.last_w));
  EXPECT_TRUE(same_bits(a.last_v, b.last_v));
  EXPECT_EQ(a.first_index, b.first_index);
  EXPECT_EQ(a.last_index, b.last_index);
  for (auto lone : {&ClusterPart::lone, &ClusterPart::before_closing}) {
    EXPECT_EQ((a.*lone).settled, (b.*lone).settled);
    EXPECT_EQ((a.*lone).head_free, (b.*lone).head_free);
    EXPECT_EQ((a.*lone).tail_free, (b.*lone).tail_free);
    EXPECT_EQ((a.*lone).single, (b.*lone).single);
  }
}

// The general path for bodies p[0 .. n), and the lane sums as DomainSampler's
// first moments pass adds them (body k of the range in lane k mod 4, the last
// n mod 4 in lane 0).
void general(const Body* p, std::size_t n, double t, double m, std::size_t index, bool closes, double (&s)[4],
             ClusterScan& scan, PeriodWrap& wrap, bool ring) {
  std::vector<double> x(n), w(n), v(n), masses(n, m);
  for (std::size_t k = 0; k < n; ++k) x[k] = p[k].at(t), v[k] = p[k].v;
  if (ring) wrap.wrap_all(x.data(), w.data(), n);
  scan.add_run(ring ? w.data() : x.data(), v.data(), masses.data(), n, index, index + n - 1, closes);
  std::size_t k = 0;
  for (; k + 4 <= n; k += 4) s[0] += p[k].v, s[1] += p[k + 1].v, s[2] += p[k + 2].v, s[3] += p[k + 3].v;
  for (; k < n; ++k) s[0] += p[k].v;
}

// A chain of n bodies from position `from`: gaps mostly small (clusters), some
// wide, some rounding-sized drops (drop_every > 0), local times before t.
std::vector<Body> random_bodies(Rng& rng, std::size_t n, double from, double L, double t, int drop_every) {
  std::vector<Body> b(n);
  double at = from;
  for (std::size_t k = 0; k < n; ++k) {
    const double u = rng.uniform();
    at += u < 0.6 ? rng.uniform(0.0, 1e-6) * L : rng.uniform(0.0, 2e-3) * L;
    const double v = u < 0.3 ? 0.25 : rng.uniform(-1.0, 1.0);
    const double tb = rng.uniform() < 0.5 ? t : rng.uniform(0.0, t);
    b[k] = {at - v * (t - tb), v, tb};
    if (drop_every > 0 && k > 0 && k % static_cast<std::size_t>(drop_every) == 0)
      b[k] = {std::nextafter(b[k - 1].at(t), -1e300), v, t};
  }
  return b;
}

// Runs as DomainSampler cuts a range: of `run` bodies, the last shorter; the
// first run's first body closes the chain (when the stretch starts with it,
// it is not counted inside), and the general path against add() body by body.
void expect_sweep_equals_general(const std::vector<Body>& b, double t, double L, bool ring,
                                 const ClusterCriteria& criteria, double m, const MultiParticleRule& rule,
                                 std::size_t& swept) {
  SampleSpec spec{true, criteria, rule, L, ring};
  ClusterScan fast(spec), slow(spec), single(spec);
  PeriodWrap fast_wrap(L), slow_wrap(L);
  double fs[4] = {0, 0, 0, 0}, ss[4] = {0, 0, 0, 0};
  constexpr std::size_t run = 256;
  for (std::size_t lo = 0; lo < b.size(); lo += run) {
    const std::size_t n = std::min(run, b.size() - lo);
    const bool closes = lo == 0;
    const bool done = ring ? sweep_run<true>(b.data() + lo, n, t, m, lo, closes, fs, fast, fast_wrap)
                           : sweep_run<false>(b.data() + lo, n, t, m, lo, closes, fs, fast, fast_wrap);
    if (!done) {
      double unused[4] = {0, 0, 0, 0};
      general(b.data() + lo, n, t, m, lo, closes, unused, fast, fast_wrap, ring);
    }
    swept += done;
    general(b.data() + lo, n, t, m, lo, closes, ss, slow, slow_wrap, ring);
    for (std::size_t k = 0; k < n; ++k) {
      const double x = b[lo + k].at(t);
      single.add(ring ? wrap_into(x, L) : x, b[lo + k].v, m, lo + k, closes && k == 0);
    }
  }
  for (int k = 0; k < 4; ++k) EXPECT_TRUE(same_bits(fs[k], ss[k])) << "lane " << k;
  expect_same_part(fast.part(), slow.part());
  expect_same_part(slow.part(), single.part());
}

// Criteria with a pair exactly on an edge (gap < max_gap and |dv| < max_dv are
// strict): its own gap as max_gap (every |dv| below max_dv), or its own |dv|
// as max_dv (every gap below max_gap).
ClusterCriteria criteria_at_a_pair(const std::vector<Body>& b, double t, double L, bool ring, bool gap,
                                   Rng& rng) {
  if (b.size() < 2) return {0.5 * L, 0.3};
  const std::size_t k = 1 + static_cast<std::size_t>((b.size() - 1) * rng.uniform());
  const double w = ring ? wrap_into(b[k].at(t), L) : b[k].at(t);
  const double w_l = ring ? wrap_into(b[k - 1].at(t), L) : b[k - 1].at(t);
  if (gap) return {w - w_l, 10.0};
  return {2 * L, std::abs(b[k].v - b[k - 1].v)};
}

TEST(SampleSweep, EqualsTheGeneralPathToTheBit) {
  Rng rng(61);
  std::size_t swept = 0, runs = 0;
  for (double L : {1.0, 3000.0, 1e7, 0.1 * 3}) {
    for (int trial = 0; trial < 60; ++trial) {
      SCOPED_TRACE("L = " + std::to_string(L) + ", trial " + std::to_string(trial));
      const bool ring = trial % 4 != 3;
      const std::size_t n = 1 + static_cast<std::size_t>(1500 * rng.uniform());
      // Inside a period, from just below a boundary, or within rounding of 0
      // (below the first period's lo = 2^-40 L, or in the period below).
      const double k = trial % 5 == 0 ? std::floor(rng.uniform(-1500.0, 1500.0)) : 0.0;
      double from = trial % 3 == 0 ? (k + 1) * L - 1e-4 * L : (k + rng.uniform(0.0, 0.5)) * L;
      if (trial % 11 == 5) from = (trial % 2 == 0 ? 1e-13 : -1e-13) * L;
      const double t = rng.uniform(0.5, 10.0);
      const std::vector<Body> b = random_bodies(rng, n, from, L, t, trial % 7 == 1 ? 97 : 0);
      const ClusterCriteria criteria = trial % 2 == 0
                                           ? default_cluster_criteria(0.02, 1.0)
                                           : criteria_at_a_pair(b, t, L, ring, trial % 3 == 0, rng);
      // Bodies of mass 1 against 1.5 M / N = 1.5 (light: lone ones left out) or 0.75 (heavy).
      const MultiParticleRule rule(trial % 4 == 1 ? 0.5 : 1.0);
      expect_sweep_equals_general(b, t, L, ring, criteria, 1.0, rule, swept);
      runs += (n + 255) / 256;
    }
  }
  EXPECT_GT(swept, runs / 2);  // the sweep itself was tested, not only its fallback
  EXPECT_LT(swept, runs);      // ... and the fallback too
}

// add_run with a mass per body (the linked engine's runs) against add() body by
// body: wrapped positions with a seam (ring), rounding-sized drops, equal
// positions, masses light and heavy, indices with gaps (merged bodies) and the
// closing body (index below its left one's) starting a run, as DomainSampler
// cuts them.
TEST(SampleSweep, RunsOfBodiesOfAnyMassEqualBodyByBody) {
  Rng rng(62);
  for (int trial = 0; trial < 300; ++trial) {
    SCOPED_TRACE("trial " + std::to_string(trial));
    const bool ring = trial % 3 != 2;
    const std::size_t n = 1 + static_cast<std::size_t>(700 * rng.uniform());
    const double L = static_cast<double>(2 * n);
    std::vector<double> w(n), v(n), m(n);
    std::vector<std::size_t> index(n);
    const std::size_t closing = static_cast<std::size_t>(static_cast<double>(n) * rng.uniform());
    double x = rng.uniform(0.0, L), u = 0;
    for (std::size_t k = 0; k < n; ++k) {
      const double r = rng.uniform();
      x = r < 0.05 ? x : r < 0.08 ? std::nextafter(x, -1e300) : x + rng.uniform(0.0, 3.0);
      if (ring && x >= L) x -= L;  // the seam
      u = r < 0.6 ? u + rng.uniform(-0.03, 0.03) : rng.uniform(-1.0, 1.0);
      w[k] = x, v[k] = u, m[k] = r < 0.5 ? 1.0 : r < 0.8 ? 2.0 : rng.uniform(0.5, 3.0);
      index[k] = ring && k >= closing ? k - closing : n + 3 * k;  // the ring's order from body 0 wraps
    }
    const SampleSpec spec{true, {rng.uniform(0.0, 2.0), 0.05}, MultiParticleRule(1.0), L, ring};
    ClusterScan runs(spec), single(spec);
    for (std::size_t lo = 0; lo < n;) {
      std::size_t hi = std::min(n, lo + 1 + static_cast<std::size_t>(300 * rng.uniform()));
      if (ring && closing > lo && closing < hi) hi = closing;  // the closing body starts a run
      const bool closes = ring && lo == closing && lo > 0;
      runs.add_run(&w[lo], &v[lo], &m[lo], hi - lo, index[lo], index[hi - 1], closes);
      for (std::size_t k = lo; k < hi; ++k) single.add(w[k], v[k], m[k], index[k], closes && k == lo);
      lo = hi;
    }
    expect_same_part(runs.part(), single.part());
  }
}

}  // namespace
}  // namespace shockgas::particles::detail

#endif
