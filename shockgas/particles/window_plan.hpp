#pragma once
// Where the chain can be cut for a while (private to particles/): the cuts of a
// window plan and how long each surely stays open. Used by WindowScheduler.
//
// Causality. With equal masses and 0 <= r <= 1 a collision replaces the two
// velocities by convex combinations of themselves (collision.hpp); a merge (r = 0
// with unequal masses too) replaces them by their mass-weighted mean. So from
// time T on every velocity stays in [v_min, v_max] of time T, and a pair with gap
// G at T cannot meet before T + G / (v_max - v_min). Until then such a pair, a
// cut, separates the bodies on its two sides: no collision on one side can change
// a body on the other. (An elastic bounce of unequal masses is not convex: a light
// body can leave the range, so those rules keep the global queue.)
//
// Cuts: near every D-th pair (D about domain_bodies), the pair with the widest gap
// among the D/8 pairs on either side. Cuts whose bound is below a quarter of the
// median bound are dropped (their domains join), so that one dense cluster does
// not shorten every window. The smallest bound kept is the plan's length; then
// the candidates near every fine_bodies-th pair that hold that long are cut too
// (refine), where a plan holds many collisions per body. Everything here is a
// function of the state alone, computed per candidate (in parallel): the same
// cuts for any number of threads.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "shockgas/core/thread_team.hpp"
#include "shockgas/particles/event_engine.hpp"

namespace shockgas::particles::detail {

template <bool Linked>
class WindowPlanner {
 public:
  using Engine = EventEngine<Linked>;
  static constexpr std::size_t none = Engine::none;
  // Nominal bodies per domain: a domain's bodies and tree (~150 kB) stay in the
  // second-level cache.
  static constexpr std::size_t domain_bodies = 4096;
  // Nominal bodies per domain of a refined plan (refine): a domain's bodies and
  // tree (~20 kB) in the first-level cache.
  static constexpr std::size_t fine_bodies = 512;
  // At least this many coarse domains; windows need min_domains x
  // min_domain_bodies bodies (window_obstacle). Refined domains may hold fewer.
  static constexpr std::size_t min_domains = 4;
  static constexpr std::size_t min_domain_bodies = 256;

  explicit WindowPlanner(const Engine& e) : e_(e) {}

  // The cuts at time t for a velocity spread of at most dv, ascending, and how
  // long they surely stay open (+inf on a line without cuts; 0 when no cut can
  // open: then cuts is empty).
  double choose(double t, double dv, ThreadTeam& team, std::vector<std::size_t>& cuts) {
    const std::size_t domains = std::max(min_domains, n() / domain_bodies);
    const std::size_t k0 = first_candidate();
    find_candidates(domains, t, dv, team);
    std::vector<double> sorted;
    for (std::size_t k = k0; k < domains; ++k)
      if (candidate_[k] != none) sorted.push_back(bound_[k]);
    cuts.clear();
    if (sorted.empty()) return e_.ring_ ? 0.0 : std::numeric_limits<double>::infinity();
    std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
    const double keep = 0.25 * sorted[sorted.size() / 2];
    double lookahead = std::numeric_limits<double>::infinity();
    for (std::size_t k = k0; k < domains; ++k) {
      if (candidate_[k] == none || bound_[k] < keep) continue;
      cuts.push_back(candidate_[k]);
      lookahead = std::min(lookahead, bound_[k]);
    }
    std::sort(cuts.begin(), cuts.end());
    if (e_.ring_ && cuts.size() < 2) cuts.clear(), lookahead = 0.0;  // a ring needs two cuts to split
    return lookahead;
  }

  // Adds to the cuts of choose (ascending) the candidates near every
  // fine_bodies-th pair that surely stay open for the whole plan, lookahead from
  // t: the plan is as long as before, and its domains, where the gas allows, an
  // eighth of the size, so a collision climbs three levels less of its domain's
  // tree. Each candidate costs a scan of 2 w + 1 gaps and its bound, so only a
  // plan of many collisions per body is worth refining (WindowScheduler).
  void refine(double t, double dv, double lookahead, ThreadTeam& team, std::vector<std::size_t>& cuts) {
    const std::size_t fine = n() / fine_bodies;
    if (fine <= cuts.size()) return;
    find_candidates(fine, t, dv, team);
    for (std::size_t k = first_candidate(); k < fine; ++k)
      if (candidate_[k] != none && bound_[k] >= lookahead) cuts.push_back(candidate_[k]);
    std::sort(cuts.begin(), cuts.end());
    cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
  }

  // Widens [lo, hi] by the velocities of bodies a .. b - 1.
  void fold_velocities(std::size_t a, std::size_t b, double& lo, double& hi) const {
    double lo4[4] = {lo, lo, lo, lo}, hi4[4] = {hi, hi, hi, hi};  // four independent chains
    for (std::size_t i = a; i < b; ++i) {
      const double v = e_.body_[i].v;
      lo4[i % 4] = std::min(lo4[i % 4], v);
      hi4[i % 4] = std::max(hi4[i % 4], v);
    }
    lo = std::min(std::min(lo4[0], lo4[1]), std::min(lo4[2], lo4[3]));
    hi = std::max(std::max(hi4[0], hi4[1]), std::max(hi4[2], hi4[3]));
  }

 private:
  std::size_t n() const { return e_.n_; }
  std::size_t wrap(std::size_t i) const { return i >= n() ? i - n() : i; }
  // On a line the nominal cut at body 0 is skipped: the line's first pairs.
  std::size_t first_candidate() const { return e_.ring_ ? 0 : 1; }

  // candidate_[k]: the widest pair near body k n / count (none if there is none),
  // bound_[k]: its bound, for k from first_candidate(); in parallel, by index.
  void find_candidates(std::size_t count, double t, double dv, ThreadTeam& team) {
    const std::size_t w = n() / count / 8;
    candidate_.assign(count, none);
    bound_.assign(count, 0.0);
    std::atomic<std::size_t> next{first_candidate()};
    team.run([&](std::size_t) {
      for (std::size_t k = next++; k < count; k = next++) {
        const std::size_t c = widest_near(k * n() / count, w, t);
        candidate_[k] = c;
        if (c != none) bound_[k] = cut_bound(c, t, dv);
      }
    });
  }

  // Gap of the pair (i, j = right(i)) at time t.
  double gap(std::size_t i, std::size_t j, double t) const {
    return (e_.body_[j].at(t) + e_.shift(i, j)) - e_.body_[i].at(t);
  }

  // The gap of slot i at t less its rounding: a few ulps of the positions (they
  // reach L on a ring) and 1e-6 relative for the rounding of the velocities.
  double safe_gap(std::size_t i, std::size_t j, double t) const {
    const double slack = 1e-12 * (e_.L_ + std::abs(e_.body_[i].x));
    return std::max((1.0 - 1e-6) * gap(i, j, t) - slack, 0.0);
  }

  // How long from t the cut c (pair c, j = right(c)) surely stays open. A chain
  // of collisions carries velocity from a body k to body c by moving bodies (at
  // most v_max) while c moves at least at v_min, so from body k it reaches c no
  // sooner than (x_c - x_k) / dv, dv = v_max - v_min; likewise from the right to
  // j. Until t + D, then, c and j keep velocities within those of the bodies at
  // most dv D away on their side (max_L on the left, min_R on the right), and the
  // gap G closes at most at max_L - min_R: the cut holds while G > (max_L - min_R) D.
  // (The first cut to close would have to break this bound first.) Scans up to
  // `reach` bodies; never less than the global bound G / dv.
  double cut_bound(std::size_t c, double t, double dv) const {
    constexpr int reach = 64;
    const double inf = std::numeric_limits<double>::infinity();
    if (!(dv > 0)) return inf;
    const auto& body = e_.body_;
    const std::size_t r = e_.right(c);
    const double G = safe_gap(c, r, t);
    auto at = [&](std::size_t k) { return body[k].at(t); };
    const double xl = at(c), xr = at(r) + e_.shift(c, r);
    double max_l = body[c].v, min_r = body[r].v;
    // Next bodies outward and their distances (unrolled); +inf past a line's end.
    std::size_t kl = c, kr = r;
    double shift_l = 0, shift_r = e_.shift(c, r);
    auto step_left = [&]() {
      const std::size_t k = e_.left(kl);
      if (k == none) return inf;
      if (k > kl) shift_l -= e_.L_;
      kl = k;
      return xl - (at(kl) + shift_l);
    };
    auto step_right = [&]() {
      const std::size_t k = e_.right(kr);
      if (k == none) return inf;
      if (k < kr) shift_r += e_.L_;
      kr = k;
      return at(kr) + shift_r - xr;
    };
    double dl = step_left(), dr = step_right();
    const double slack = 1e-12 * (e_.L_ + std::abs(xl));  // rounding of the distances, as in safe_gap
    double bound = G / dv;
    for (int k = 0; k < 2 * reach; ++k) {
      const double horizon = (std::min(dl, dr) - slack) / dv;  // the sets are complete until then
      const double d = max_l > min_r ? G / (max_l - min_r) : inf;
      if (d <= horizon) return std::max(d, G / dv);
      bound = std::max(bound, horizon);
      if (dl <= dr) {
        max_l = std::max(max_l, body[kl].v);
        dl = std::max(dl, step_left());  // rounding aside, distances grow outward
      } else {
        min_r = std::min(min_r, body[kr].v);
        dr = std::max(dr, step_right());
      }
    }
    return bound;
  }

  // The widest pair of live bodies among slots c - w .. c + w (mod n on a ring,
  // inside the line); none if there is none.
  std::size_t widest_near(std::size_t c, std::size_t w, double t) const {
    if constexpr (!Linked) return widest_near_equal(c, w, t);
    std::size_t best = none;
    double widest = -std::numeric_limits<double>::infinity();
    for (std::size_t d = 0; d <= 2 * w; ++d) {
      const std::size_t i = wrap(c + n() - w + d);
      if (!e_.live(i)) continue;
      const std::size_t j = e_.right(i);
      if (j == none) continue;
      const double g = gap(i, j, t);
      if (g > widest) widest = g, best = i;
    }
    return best;
  }

  // widest_near without merges: the slots in the same order, each body's
  // position at t computed once (the right body of one pair is the left of the
  // next, body wrap(i + 1)).
  std::size_t widest_near_equal(std::size_t c, std::size_t w, double t) const {
    std::size_t best = none;
    double widest = -std::numeric_limits<double>::infinity();
    std::size_t i = wrap(c + n() - w);
    double xi = e_.body_[i].at(t);
    for (std::size_t d = 0; d <= 2 * w; ++d) {
      const std::size_t j = e_.right(i);
      const std::size_t next = wrap(i + 1);
      const double xj = e_.body_[next].at(t);
      if (j != none) {
        const double g = (xj + e_.shift(i, j)) - xi;
        if (g > widest) widest = g, best = i;
      }
      i = next, xi = xj;
    }
    return best;
  }

  const Engine& e_;
  std::vector<std::size_t> candidate_;  // per nominal cut (find_candidates): the widest pair near it, or none
  std::vector<double> bound_;           // its bound
};

// Why time windows are not exact for n bodies under this rule ("" when they are),
// and what they would need. They are exact when every collision keeps the
// velocities in their range (equal masses without merges, or merges only) and no
// inelastic collapse must be detected.
inline std::string window_obstacle(std::size_t n, bool equal_masses, const CollisionRule& rule) {
  if (rule.collapse_possible())
    return "inelastic collapse is possible (delta = 0 and 0 < r < 1, or a restitution law): detecting it "
           "needs the global time order; windows would need a collapse test per domain";
  if (n < WindowPlanner<false>::min_domains * WindowPlanner<false>::min_domain_bodies)
    return "fewer than 1024 bodies: too few to split";
  if (rule.law && !rule.merges_only())
    return "a restitution law r(g): the windows' step computes the two bounces of a constant r once; "
           "windows would need r(g) per collision in DomainStepper";
  if (rule.merges_only() || (equal_masses && !rule.can_merge())) return "";
  const char* need =
      "; windows would need a bound on how far a velocity can leave its range in a window (or cuts checked "
      "after each window, with a rollback)";
  if (rule.can_merge())
    return std::string(
               "sticky sub-threshold with r > 0: merged bodies of unequal mass bounce inelastically, which "
               "can leave the velocity range, so the window bound does not hold") +
           need;
  return std::string(
             "unequal masses with bounces: a bounce of a light body off a heavy one can leave the velocity "
             "range, so the window bound does not hold") +
         need;
}

}  // namespace shockgas::particles::detail
