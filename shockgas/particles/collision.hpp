#pragma once
// The collision rule of the gas: the physics of shockgas::particles in one place.
// The engine, its time windows and the benchmark's baseline call these functions
// (inlined), and write no bounce or merge of their own.
//
// Two neighbouring bodies, left (mass mL, velocity v) and right (mass mR,
// velocity u), meet with approach speed g = v - u > 0. With restitution r:
//
//     v' = v - (1 + r) mR / (mL + mR) g,    u' = u + (1 + r) mL / (mL + mR) g,
//
// which keeps the momentum mL v + mR u and maps g -> -r g. The kinetic energy lost
// is (1 - r^2) mu g^2 / 2 with the reduced mass mu = mL mR / (mL + mR). With equal
// masses, v' = (1 - r)/2 v + (1 + r)/2 u and u' = (1 + r)/2 v + (1 - r)/2 u: for
// 0 <= r <= 1 convex combinations of v and u (what the time windows rely on,
// window_plan.hpp).
//
// Kinds (Ben-Naim, Chen, Doolen & Redner, PRL 83, 4069 (1999)):
//  * r = 0: a merge, whatever g. The completely inelastic gas is the sticky gas
//    ("particles aggregate upon collision"); it has no inelastic collapse, so the
//    threshold has nothing to bypass and delta does not apply.
//  * r > 0, g < delta: sub-threshold. Elastic (r = 1) by default, or, with
//    subthreshold = "sticky", a merge.
//  * r > 0, g >= delta: an inelastic collision, of restitution r, or r(g) where
//    the rule has a restitution law (restitution_laws.hpp).
// A merge is a true aggregation: one body of mass mL + mR at the centre-of-mass
// velocity (mL v + mR u) / (mL + mR), losing mu g^2 / 2. Point particles with
// r = 0 but no merge would collide infinitely often inside a cluster.
#include <array>
#include <cassert>
#include <cstddef>
#include <cstdint>
#include <functional>

namespace shockgas::particles {

enum class CollisionKind : std::uint8_t {
  inelastic = 0,  // g >= delta, 0 < r <= 1
  elastic = 1,    // r > 0, g < delta, sub-threshold elastic
  merge = 2,      // r = 0, or r > 0 and g < delta with sticky sub-threshold
};

// A velocity-dependent restitution: r(g) in (0, 1] of an inelastic collision
// with approach speed g >= delta, in place of the constant r.
using RestitutionLaw = std::function<double(double g)>;

// The rule's parameters, fixed for a run.
struct CollisionRule {
  double r = 0.9;                    // restitution [1], 0 <= r <= 1
  double delta = 1e-2;               // sub-threshold velocity [length/time], >= 0; r > 0 only
  bool sticky_subthreshold = false;  // sub-threshold collisions merge instead of bouncing (r > 0)
  RestitutionLaw law = {};           // r(g) of the inelastic collisions (r > 0); empty: the constant r

  // True when some collision of this rule can merge bodies.
  bool can_merge() const { return r == 0.0 || (sticky_subthreshold && delta > 0.0); }

  // Inelastic collapse needs inelastic collisions at arbitrarily small approach
  // speeds: delta = 0 and 0 < r < 1 (or a law, whose r(g) may be below 1).
  bool collapse_possible() const { return delta == 0.0 && r > 0.0 && (r < 1.0 || law); }

  // True when every collision of this rule is a merge: r = 0.
  bool merges_only() const { return r == 0.0; }

  // Kind of a collision with approach speed g > 0.
  CollisionKind classify(double g) const {
    if (merges_only()) return CollisionKind::merge;
    if (g < delta) return sticky_subthreshold ? CollisionKind::merge : CollisionKind::elastic;
    return CollisionKind::inelastic;
  }

  // Restitution of a non-merging collision of this kind and approach speed g.
  // HasLaw: whether law is set, decided once per run outside the engine's loop
  // (EventEngine::run_until), so that the constant rule's collisions test nothing.
  template <bool HasLaw>
  double restitution(CollisionKind kind, double g) const {
    if (kind == CollisionKind::elastic) return 1.0;
    if constexpr (HasLaw)
      return law(g);
    else
      return r;
  }
  // The same for a rule without a law.
  double restitution(CollisionKind kind) const {
    assert(!law);
    return restitution<false>(kind, 0.0);
  }
};

// Velocities after a bouncing collision with restitution r (unequal masses).
// v, u: left and right velocities in; overwritten with the velocities out.
// Returns the kinetic energy lost.
inline double bounce(double& v, double& u, double mL, double mR, double r) {
  const double g = v - u;
  const double M = mL + mR;
  v -= (1.0 + r) * (mR / M) * g;
  u += (1.0 + r) * (mL / M) * g;
  return 0.5 * (1.0 - r * r) * (mL * mR / M) * g * g;
}

// The equal-mass bounce of restitution r as factors of the approach speed g:
// v' = v - dv, u' = u + dv with dv = (1 + r) g / 2; energy lost (1 - r^2) m g^2 / 4.
struct EqualMassBounce {
  double half = 0;  // (1 + r) / 2 [1]
  double loss = 0;  // (1 - r^2) m / 4 [mass]

  static EqualMassBounce of(double r, double m) { return {0.5 * (1.0 + r), 0.25 * (1.0 - r * r) * m}; }
  double dv(double g) const { return half * g; }
  double lost(double g) const { return loss * g * g; }
};

// The equal-mass bounces of a rule's two bouncing kinds, computed once for a
// loop; indexed by CollisionKind (inelastic 0, elastic 1). Stored factor by
// factor (the two halves side by side, then the two losses), the layout the
// windows' step was tuned with.
class EqualMassBounces {
 public:
  EqualMassBounces(const CollisionRule& rule, double m)
      : EqualMassBounces(EqualMassBounce::of(rule.restitution(CollisionKind::inelastic), m),
                         EqualMassBounce::of(rule.restitution(CollisionKind::elastic), m)) {}
  EqualMassBounce operator[](std::size_t kind) const { return {half_[kind], loss_[kind]}; }

 private:
  EqualMassBounces(EqualMassBounce inelastic, EqualMassBounce elastic)
      : half_{inelastic.half, elastic.half}, loss_{inelastic.loss, elastic.loss} {}
  std::array<double, 2> half_, loss_;
};

struct VelocityPair {
  double v = 0;  // left [length/time]
  double u = 0;  // right
};

// Equal masses after exchanging dv: v' = v - dv, u' = u + dv (momentum kept).
inline VelocityPair exchange(double v, double u, double dv) { return {v - dv, u + dv}; }

// Equal-mass bounce: v' = v - (1 + r) g / 2, u' = u + (1 + r) g / 2.
inline double bounce_equal(double& v, double& u, double m, double r) {
  const EqualMassBounce factors = EqualMassBounce::of(r, m);
  const double g = v - u;
  const VelocityPair out = exchange(v, u, factors.dv(g));
  v = out.v;
  u = out.u;
  return factors.lost(g);
}

struct Merged {
  double v = 0;           // centre-of-mass velocity [length/time]
  double m = 0;           // summed mass [mass]
  double dissipated = 0;  // kinetic energy lost, mu g^2 / 2 [mass length^2/time^2]
};

// One body out of two: mass and momentum kept.
inline Merged merge(double v, double u, double mL, double mR) {
  const double M = mL + mR;
  const double g = v - u;
  return {(mL * v + mR * u) / M, M, 0.5 * (mL * mR / M) * g * g};
}

}  // namespace shockgas::particles
