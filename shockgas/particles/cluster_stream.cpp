// The clusters of a state read in chunks (cluster_finder.hpp: visit_clusters),
// as find_clusters finds them from a whole copy: the same walk, the same sums in
// the same order, so the same bits.
//
// find_clusters starts the walk at the first body whose left neighbour is not
// joined to it (ring), so the cluster across the wrap comes last and sums its
// members from its first body past N - 1 round to the start. Streamed: where
// the state knows its last body (StateReader::last), one read: body 0 and the
// last settle the wrap, the start is the first break, and the bodies before it
// wait (at most kHeldBeforeStart) for the last cluster. Otherwise a first read
// finds the start; a second walks from it to N - 1; a third adds the bodies
// before the start (unrolled by + L) to the last cluster.
#include <array>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

#include "shockgas/core/error.hpp"
#include "shockgas/particles/cluster_finder.hpp"
#include "shockgas/particles/cluster_sums.hpp"

namespace shockgas::particles {

namespace {

// Visits body i of the state with f(i, x, v, m), in order.
template <class F>
void each_body(const StateReader& state, F&& f) {
  std::size_t i = 0;
  state.read([&](const double* x, const double* v, const double* m, std::size_t count) {
    for (std::size_t k = 0; k < count; ++k, ++i) f(i, x[k], v[k], m[k]);
  });
}

// Where find_clusters starts on a ring: the first body not joined to its left
// neighbour (body 0's is body N - 1, across the wrap), else 0.
std::size_t ring_start(const StateReader& state, double L, const ClusterCriteria& c) {
  const std::size_t n = state.size();
  if (n < 2) return 0;
  std::size_t first_break = 0;  // none yet
  double x0 = 0, v0 = 0, x_last = 0, v_last = 0;
  each_body(state, [&](std::size_t i, double x, double v, double) {
    if (i == 0) x0 = x, v0 = v;
    if (i > 0 && first_break == 0 && !c.joins(x - x_last, v - v_last)) first_break = i;
    x_last = x, v_last = v;
  });
  return c.joins(x0 + L - x_last, v0 - v_last) ? first_break : 0;
}

// The walk: bodies handed in order from its start; a pair that does not join
// closes a cluster (close(sums): its sums, made into a Cluster by whoever needs
// it) and opens the next; bodies from before the start join the last cluster
// across the wrap, unrolled by + L.
template <class Close>
class ClusterWalk {
 public:
  ClusterWalk(double L, const ClusterCriteria& c, Close& close) : L_(L), c_(c), close_(close) {}
  void add(std::size_t i, double x, double v, double m) {
    if (started_) return add_run(i, &x, &v, &m, 1);
    sums_.start(i, x, v), started_ = true;
    sums_.add(x, v, m);
    x_last_ = x, v_last_ = v;
  }
  // add() of bodies i .. i + count - 1 of a walk already started; the sums and
  // the last body in locals through the run (the members live in memory: close
  // may write anywhere as far as the compiler knows).
  void add_run(std::size_t i, const double* x, const double* v, const double* m, std::size_t count) {
    const ClusterCriteria c = c_;
    detail::ClusterSums sums = sums_;
    double x_last = x_last_, v_last = v_last_;
    for (std::size_t k = 0; k < count; ++k, ++i) {
      if (!c.joins(x[k] - x_last, v[k] - v_last)) {
        close_(std::as_const(sums));
        sums.start(i, x[k], v[k]);
      }
      sums.add(x[k], v[k], m[k]);
      x_last = x[k], v_last = v[k];
    }
    sums_ = sums, x_last_ = x_last, v_last_ = v_last;
  }
  void add_across_wrap(double x, double v, double m) { sums_.add(x + L_, v, m); }
  bool started() const { return started_; }
  void finish() { close_(std::as_const(sums_)); }

 private:
  double L_;
  const ClusterCriteria& c_;
  Close& close_;
  detail::ClusterSums sums_;
  bool started_ = false;
  double x_last_ = 0, v_last_ = 0;
};

// The walk from `start` (ring_start), the bodies before it read from the
// state once more.
template <class Close>
void walk_from(const StateReader& state, double L, const ClusterCriteria& c, std::size_t start,
               Close& close) {
  ClusterWalk walk(L, c, close);
  each_body(state, [&](std::size_t i, double x, double v, double m) {
    if (i >= start) walk.add(i, x, v, m);
  });
  if (start > 0)  // the last cluster runs on across the wrap up to the start
    each_body(state, [&](std::size_t i, double x, double v, double m) {
      if (i < start) walk.add_across_wrap(x, v, m);
    });
  walk.finish();
}

// Bodies before the start that one read holds back for the cluster across the
// wrap (24 bytes each: 1.5 MiB); past them the walk reads again.
constexpr std::size_t kHeldBeforeStart = std::size_t{1} << 16;

// The same walk in one read where the state knows its last body: on a ring
// that body settles the wrap first (whether body 0 joins it), so the start is
// known at the first break, and the bodies before it wait in a buffer.
template <class Close>
bool walk_once(const StateReader& state, double L, const ClusterCriteria& c, Close& close) {
  const std::optional<std::array<double, 3>> last = state.last();
  if (L > 0 && !last) return false;
  ClusterWalk walk(L, c, close);
  bool wraps = false;  // body 0 joins the last across the wrap: start at the first break
  bool overflow = false;
  std::vector<std::array<double, 3>> before;
  double x_last = 0, v_last = 0;
  auto body = [&](std::size_t i, double x, double v, double m) {
    if (overflow) return;  // given up before the start: nothing visited, the three-read walk follows
    if (i == 0) wraps = L > 0 && state.size() > 1 && c.joins(x + L - (*last)[0], v - (*last)[1]);
    if (walk.started() || !wraps || (i > 0 && !c.joins(x - x_last, v - v_last)))
      walk.add(i, x, v, m);
    else if (before.size() < kHeldBeforeStart)
      before.push_back({x, v, m});
    else
      overflow = true;
    x_last = x, v_last = v;
  };
  std::size_t i = 0;  // once the walk has started, the rest of each chunk goes to it as a run
  state.read([&](const double* x, const double* v, const double* m, std::size_t count) {
    std::size_t k = 0;
    for (; k < count && !walk.started(); ++k, ++i) body(i, x[k], v[k], m[k]);
    if (k < count) walk.add_run(i, x + k, v + k, m + k, count - k);
    i += count - k;
  });
  if (overflow) return false;
  if (walk.started()) {
    for (const auto& [x, v, m] : before) walk.add_across_wrap(x, v, m);
  } else {  // a ring joined all round: one cluster from body 0
    for (std::size_t k = 0; k < before.size(); ++k) walk.add(k, before[k][0], before[k][1], before[k][2]);
  }
  walk.finish();
  return true;
}

// The whole walk, each cluster's sums to close(sums) in find_clusters' order.
// A walk that gives up (too many bodies before the start) does so before its
// first close, and closes nothing after it.
template <class Close>
void walk(const StateReader& state, double L, const ClusterCriteria& c, Close& close) {
  detail::require_cluster_inputs(L, c);
  if (state.size() == 0) return;
  if (walk_once(state, L, c, close)) return;
  walk_from(state, L, c, L > 0 ? ring_start(state, L, c) : 0, close);
}

}  // namespace

void visit_clusters(const StateReader& state, double L, const ClusterCriteria& c,
                    const std::function<void(const Cluster&)>& visit) {
  auto close = [&](const detail::ClusterSums& sums) { visit(sums.done(L)); };
  walk(state, L, c, close);
}

// Only a cluster heavier than the heaviest so far is made (its sums' mass is
// the Cluster's m, bit for bit).
std::optional<Cluster> heaviest_cluster(const StateReader& state, double L, const ClusterCriteria& c) {
  std::optional<Cluster> heaviest;
  auto close = [&](const detail::ClusterSums& sums) {
    if (!heaviest || heaviest->m < sums.mass()) heaviest = sums.done(L);
  };
  walk(state, L, c, close);
  return heaviest;
}

}  // namespace shockgas::particles
