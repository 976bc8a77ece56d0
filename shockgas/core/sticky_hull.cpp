// The exact sticky-particle solution by the lower convex hull (E, Rykov & Sinai
// 1996; Brenier & Grenier 1998).
//
// Algorithm. The lower convex hull of the cumulative points (M_k, S_k) is built
// by a monotone chain written in cluster form (pool-adjacent-violators): bodies
// are pushed left to right as one-body clusters, and while the cluster below the
// top of the stack would sit to the right of the top one at time t,
//
//     x_left(t) > x_right(t),   x(t) = c0 + t v,  c0 = centre of mass at 0, v = mean velocity,
//
// (or x_left(t) = x_right(t) with v_left > v_right: see Ties) the two merge (mass and momentum add). x(t) is
// the slope of a hull edge, so this is exactly the convexity test of the chain, but it compares positions of
// neighbouring clusters instead of subtracting large cumulative sums S_k. O(N),
// one pass; the stack is the runs' own arrays, 20 bytes a run (c0, v, count)
// when the masses are equal (a run's mass is then m0 count), 28 with masses.
//
// Later times. Clusters only merge, so every cluster at a later time t' is a
// union of consecutive clusters at t: a hull vertex at t' is a vertex at t (an
// extreme point of the cumulative points stays extreme among a subset holding
// it). The hull at t' of the clusters at t, each pushed as one body of its mass,
// momentum and centre of mass, is therefore the hull at t' of the bodies. The
// stack overwrites the runs it has read: in place.
//
// Ties. Clusters at the same point at t merge if they approach (v_left >
// v_right): they collide at exactly t, and the event engine has made that
// collision by t. Those that touch and separate (or move together) stay apart.
// This is the hull at t + 0: positions compared first, then -v. Because exact
// ties in doubles are decided by rounding anyway, it only fixes which of two
// answers that agree in position to rounding is returned.
//
// Ring. The periodically unrolled chain (body i + N is body i moved by L) has a
// periodic hull, and no cluster holds more than N bodies. One period, bodies
// 0 .. N-1, is pushed as a line; every run of that line lies inside one cluster
// of the ring (its vertices include the ring's, as above), and only the clusters
// across the period's ends are cut. Closing the ring pools them: while the last
// run would be to the right of the first one moved by one period, they merge,
// cascading on both sides; then no two cyclic neighbours overlap, which is the
// hull. Runs absorbed from the front move the chain's start (origin_) and are
// counted at x + L inside the last run. The test is Galilean invariant, so no
// frame (mean velocity) is removed.
#include "shockgas/core/sticky_hull.hpp"

#include <sys/mman.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "shockgas/core/error.hpp"

namespace shockgas {

namespace {

// Throws InputError naming the first bad body; called only when build() found one.
void check_bodies(BodiesView b, double L) {
  for (std::size_t i = 0; i < b.size(); ++i) {
    if (!(std::isfinite(b.x[i]) && std::isfinite(b.v[i])))
      throw InputError("bodies.x/v", to_text(b.x[i]) + ", " + to_text(b.v[i]), "finite values");
    if (!(b.m[i] > 0 && std::isfinite(b.m[i])))
      throw InputError("bodies.m", to_text(b.m[i]), "finite masses > 0");
    if (i > 0 && !(b.x[i] >= b.x[i - 1]))
      throw InputError("bodies.x", to_text(b.x[i]), "positions sorted ascending");
  }
  if (L == 0 || b.size() == 0) return;
  const double outside = b.x.front() < 0 ? b.x.front() : b.x.back();  // sorted: an end is out if any is
  require(outside >= 0 && outside < L, "bodies.x", outside, "positions in [0, L)");
}

void check_arguments(BodiesView b, double t) {
  require_in_range("t", t, 0.0, std::numeric_limits<double>::max());
  require(b.v.size() == b.size() && b.m.size() == b.size(), "bodies", b.size(), "x, v and m of equal length");
  require(b.size() <= std::numeric_limits<std::uint32_t>::max(), "bodies", b.size(),
          "at most 2^32 - 1 bodies");
}

}  // namespace

namespace {

// n elements left uninitialised (each is written before it is read): std::make_unique_for_overwrite,
// or the same by new T[n] where the standard library lacks it (libc++ 14, the lab's WebAssembly build).
template <class T>
std::unique_ptr<T[]> uninitialised(std::size_t n) {
#if defined(__cpp_lib_smart_ptr_for_overwrite)
  return std::make_unique_for_overwrite<T[]>(n);
#else
  return std::unique_ptr<T[]>(new T[n]);
#endif
}

}  // namespace

StickyHull::StickyHull(std::size_t n, double L, double t, bool masses)
    : n_(n),
      L_(L),
      t_(t),
      masses_(masses),
      c0_(uninitialised<double>(n)),
      v_(uninitialised<double>(n)),
      m_(masses ? uninitialised<double>(n) : nullptr),
      count_(uninitialised<std::uint32_t>(n)) {}

namespace {

// The bodies of one step of the build's pass: room is made for them at once.
constexpr std::size_t kBuildBlock = 4096;

// Makes [from, to) elements of `base` resident in one system call, ahead of
// their first writes: a page fault per 4 KiB costs about as much as the hull's
// own work on the 200 runs it holds. A hint: where unsupported, pages fault in.
void prefault(void* base, std::size_t from, std::size_t to, std::size_t size) {
#if defined(__linux__) && defined(MADV_POPULATE_WRITE)
  constexpr std::uintptr_t page = 4096;
  const auto address = reinterpret_cast<std::uintptr_t>(base);
  const std::uintptr_t a = (address + from * size) / page * page;
  const std::uintptr_t e = (address + to * size + page - 1) / page * page;
  madvise(reinterpret_cast<void*>(a), e - a, MADV_POPULATE_WRITE);
#else
  (void)base, (void)from, (void)to, (void)size;
#endif
}

// Whether a cluster at xl (velocity vl) and its right neighbour at xr (vr),
// positions at t, have met by t: overlapping, or at one point and approaching
// (a collision at exactly t, which the event engine has made by t; see Ties).
inline bool met_by_t(double xl, double vl, double xr, double vr) { return xl > xr || (xl == xr && vl > vr); }

// The stack of runs [0, top) over the hull's arrays, with the top's position at
// t kept in a register. Without masses, a run's weight is its count. Runs below
// `ready` are resident; reserve() makes room for a block of pushes (each adds at
// most one run) in steps of 2^14 runs: only the depth reached is resident.
template <bool Masses>
struct Stack {
  static constexpr std::size_t step = std::size_t{1} << 14;
  double* c0;
  double* v;
  double* m;
  std::uint32_t* count;
  double t;
  std::size_t capacity;
  std::size_t ready = 0;
  std::size_t top = 0;
  double top_x = -std::numeric_limits<double>::infinity();  // -inf: empty

  // Pushes a cluster (centre of mass c at t = 0, velocity u, weight w, k
  // bodies), merging while the run below has met it by t: it is to the right
  // of it at t, or at the same point and approaching (a collision at exactly t,
  // which the event engine has made by t too).
  void push(double c, double u, double w, std::uint32_t k) {
    double x = c + t * u;
    while (top > 0 && met_by_t(top_x, v[top - 1], x, u)) {
      const std::size_t b = top - 1;
      const double total = (Masses ? m[b] : static_cast<double>(count[b])) + w;
      const double share = w / total;
      c = c0[b] + share * (c - c0[b]);
      u = v[b] + share * (u - v[b]);
      w = total;
      k += count[b];
      x = c + t * u;
      top = b;
      top_x = top > 0 ? c0[top - 1] + t * v[top - 1] : -std::numeric_limits<double>::infinity();
    }
    c0[top] = c, v[top] = u, count[top] = k;
    if constexpr (Masses) m[top] = w;
    ++top;
    top_x = x;
  }

  // Makes room for `pushes` more pushes.
  void reserve(std::size_t pushes) {
    if (top + pushes <= ready) return;
    const std::size_t to = std::min(capacity, std::max(top + pushes, ready + step));
    prefault(c0, ready, to, sizeof(double));
    prefault(v, ready, to, sizeof(double));
    prefault(count, ready, to, sizeof(std::uint32_t));
    if constexpr (Masses) prefault(m, ready, to, sizeof(double));
    ready = to;
  }
};

}  // namespace

// One pass over the bodies, room made per block of kBuildBlock (block(begin, count):
// the bodies [begin, begin + count)). Validity is folded into it (branch-free)
// and judged at the end: x_i >= x_{i-1} for all i and finite ends make every x
// finite. Unequal masses without Masses: stops, and the caller starts again.
template <bool Masses, class Block>
StickyHull::Built StickyHull::build(Block&& block) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  bool valid = true;
  double previous = -inf, first = 0, vmax = 0;
  Stack<Masses> stack{c0_.get(), v_.get(), m_.get(), count_.get(), t_, n_};
  for (std::size_t begin = 0; begin < n_; begin += kBuildBlock) {
    const std::size_t end = std::min(n_, begin + kBuildBlock);
    const BlockPointers b = block(begin, end - begin);
    if (begin == 0) {
      m0_ = b.m[0], first = b.x[0];
      valid = m0_ > 0 && m0_ < inf;
    }
    stack.reserve(end - begin);
    for (std::size_t j = 0; j < end - begin; ++j) {
      if (!Masses && b.m[j] != m0_) return Built::unequal_masses;
      const double speed = std::abs(b.v[j]);
      valid &= (b.x[j] >= previous) & (speed < inf);
      vmax = speed > vmax ? speed : vmax;
      if constexpr (Masses) valid &= (b.m[j] > 0) & (b.m[j] < inf);
      previous = b.x[j];
      stack.push(b.x[j], b.v[j], Masses ? b.m[j] : 1.0, 1);
    }
  }
  if (n_ == 0) m0_ = 1.0;
  if (n_ > 0) valid &= first > -inf && previous < inf && (L_ == 0 || (first >= 0 && previous < L_));
  if (!valid) return Built::bad_input;
  vmax_ = vmax;
  reach_x_ = n_ > 0 ? std::max(std::abs(first), std::abs(previous)) + L_ : 0.0;
  end_ = stack.top;
  if (L_ > 0) close_ring();
  return Built::ok;
}

template <bool Masses>
void StickyHull::pool_runs() {
  Stack<Masses> stack{c0_.get(), v_.get(), m_.get(), count_.get(), t_, n_, end_};  // in place: resident
  for (std::size_t r = begin_; r < end_; ++r)
    stack.push(c0_[r], v_[r], Masses ? m_[r] : static_cast<double>(count_[r]), count_[r]);
  begin_ = 0;
  end_ = stack.top;
}

void StickyHull::close_ring() {
  // Run `right` (its centre counted at + shift) joins run `left`.
  auto merge = [&](std::size_t left, std::size_t right, double shift) {
    const double ml = masses_ ? m_[left] : static_cast<double>(count_[left]);
    const double mr = masses_ ? m_[right] : static_cast<double>(count_[right]);
    const double share = mr / (ml + mr);
    c0_[left] = c0_[left] + share * ((c0_[right] + shift) - c0_[left]);
    v_[left] = v_[left] + share * (v_[right] - v_[left]);
    if (masses_) m_[left] = ml + mr;
    count_[left] += count_[right];
  };
  auto overlaps = [&](std::size_t left, std::size_t right, double shift) {
    return met_by_t(c0_[left] + t_ * v_[left], v_[left], (c0_[right] + shift) + t_ * v_[right], v_[right]);
  };
  std::size_t front = begin_;
  while (end_ - front >= 2) {
    const std::size_t back = end_ - 1;
    if (overlaps(back, front, L_)) {
      merge(back, front, L_);
      origin_ += count_[front++];
    } else if (overlaps(back - 1, back, 0.0)) {
      merge(back - 1, back, 0.0);
      --end_;
    } else {
      break;
    }
  }
  begin_ = front;
  origin_ %= std::max<std::size_t>(n_, 1);
}

StickyHull StickyHull::line(BodiesView initial, double t) { return make(initial, 0.0, t); }

StickyHull StickyHull::ring(BodiesView initial, double L, double t) {
  require_above("L", L, 0.0);
  return make(initial, L, t);
}

StickyHull StickyHull::make(BodiesView initial, double L, double t) {
  check_arguments(initial, t);
  auto block = [&](std::size_t begin, std::size_t) {
    return BlockPointers{initial.x.data() + begin, initial.v.data() + begin, initial.m.data() + begin};
  };
  StickyHull h(initial.size(), L, t, false);
  Built built = h.build<false>(block);
  if (built == Built::unequal_masses) {
    h = StickyHull(initial.size(), L, t, true);
    built = h.build<true>(block);
  }
  if (built == Built::bad_input) check_bodies(initial, L);
  h.check_reach(t);
  return h;
}

StickyHull StickyHull::line(std::size_t n, const Chunks& read, double t) { return make(n, read, 0.0, t); }

StickyHull StickyHull::ring(std::size_t n, const Chunks& read, double L, double t) {
  require_above("L", L, 0.0);
  return make(n, read, L, t);
}

// The bodies pass once, read kReadBlocks blocks at a time (a reader that sums
// them, such as TemperatureSums, then has several blocks in a row); their
// masses must agree (a second pass with masses would need them again).
StickyHull StickyHull::make(std::size_t n, const Chunks& read, double L, double t) {
  require_in_range("t", t, 0.0, std::numeric_limits<double>::max());
  require(n <= std::numeric_limits<std::uint32_t>::max(), "bodies", n, "at most 2^32 - 1 bodies");
  constexpr std::size_t kReadBlocks = 16;  // 3 x 512 KiB
  std::vector<double> x(std::min<std::size_t>(n, kReadBlocks * kBuildBlock)), v(x.size()), m(x.size());
  std::size_t held_from = 0, held = 0;  // the bodies [held_from, held_from + held) are in x, v, m
  auto block = [&](std::size_t begin, std::size_t count) {
    if (begin + count > held_from + held) {
      held_from = begin, held = std::min(x.size(), n - begin);
      read(held, x.data(), v.data(), m.data());
    }
    const std::size_t at = begin - held_from;
    return BlockPointers{x.data() + at, v.data() + at, m.data() + at};
  };
  StickyHull h(n, L, t, false);
  const Built built = h.build<false>(block);
  if (built == Built::unequal_masses)
    throw InputError("bodies.m", "unequal masses", "bodies of one mass when they are read in chunks");
  if (built == Built::bad_input)
    throw InputError("bodies", std::to_string(n) + " bodies",
                     "positions sorted and finite (ring: in [0, L)), velocities finite, masses > 0");
  h.check_reach(t);
  return h;
}

void StickyHull::advance(double t) {
  require(std::isfinite(t) && t >= t_, "t", t, "a finite time >= the hull's time " + to_text(t_));
  check_reach(t);
  t_ = t;
  masses_ ? pool_runs<true>() : pool_runs<false>();
  if (L_ > 0) close_ring();
}

// |x + t v| <= max|x| + t max|v|; a margin of 2 covers the sums of the merges
// (a centre and a velocity averaged separately) and the ring's shifts. Bodies
// that do not move (t max|v| = 0) are where they were given.
void StickyHull::check_reach(double t) const {
  const double limit = std::numeric_limits<double>::max() / 2;
  const double travel = t * vmax_;
  if (travel == 0 || reach_x_ + travel < limit) return;
  const std::string why = ": x + t v must stay within the range of doubles";
  if (reach_x_ >= limit)
    throw InputError("bodies.x", to_text(reach_x_),
                     "max |x| (plus L on a ring) below " + to_text(limit) + why);
  throw InputError("t", to_text(t),
                   "at most " + to_text((limit - reach_x_) / vmax_) + " for these bodies" + why);
}

// The ring's period is in cyclic order of x: x ascends from the lowest wrapped x.
StickyHull::Start StickyHull::lowest() const {
  Start best{begin_, origin_};
  double lowest_x = std::numeric_limits<double>::infinity();
  std::size_t first = origin_;
  for (std::size_t k = begin_; k < end_; ++k) {
    const double x = wrapped(c0_[k] + t_ * v_[k]);
    if (x < lowest_x) lowest_x = x, best = {k, first};
    first += count_[k];
    if (first >= n_) first -= n_;
  }
  return best;
}

std::vector<StickyCluster> StickyHull::clusters() const {
  std::vector<StickyCluster> out;
  out.reserve(size());
  for_each_by_x([&](const StickyCluster& c) { out.push_back(c); });
  return out;
}

std::vector<StickyCluster> sticky_clusters_line(BodiesView initial, double t) {
  return StickyHull::line(initial, t).clusters();
}

std::vector<StickyCluster> sticky_clusters_ring(BodiesView initial, double L, double t) {
  return StickyHull::ring(initial, L, t).clusters();
}

Bodies to_bodies(const std::vector<StickyCluster>& clusters) {
  const auto by_x = [](const StickyCluster& a, const StickyCluster& b) { return a.x < b.x; };
  Bodies b;
  b.reserve(clusters.size());
  if (std::is_sorted(clusters.begin(), clusters.end(), by_x)) {  // what the solvers return
    for (const StickyCluster& c : clusters) b.push_back(c.x, c.v, c.m);
    return b;
  }
  std::vector<std::size_t> order(clusters.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t i, std::size_t j) { return by_x(clusters[i], clusters[j]); });
  for (std::size_t i : order) b.push_back(clusters[i].x, clusters[i].v, clusters[i].m);
  return b;
}

}  // namespace shockgas
