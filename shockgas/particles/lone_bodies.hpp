#pragma once
// The lone light bodies of a stretch of the chain (private to particles/): the
// clusters of a single particle, which the count of clusters leaves out
// (MultiParticleRule, cluster_finder.hpp). A body is lone when it joins neither
// neighbour, light when not MultiParticleRule::heavy; the count of clusters that
// hold two or more particles is the count of all clusters less the lone light
// bodies.
//
// Fed in chain order, a body is settled when the pair on its right is seen. A
// stretch leaves two ends unsettled: its first body waits for the pair across
// the cut on its left, its last body for the one on its right; with_cuts
// settles them. One body alone is both ends (single).
#include <cstddef>

namespace shockgas::particles::detail {

struct LoneBodies {
  std::size_t settled = 0;  // light bodies with both pairs inside, neither joined
  bool head_free = false;   // the first body is light, not joined on its right (inside)
  bool tail_free = false;   // the last body is light, not joined on its left (inside)
  bool single = true;       // no pair inside: head and tail are one body (or none)

  // The stretch's first body (anything before it forgotten).
  void start(bool light) { *this = {0, light, light, true}; }
  // The next body, light or not, and whether it joins the last one.
  void add(bool joins, bool light) {
    if (single)
      head_free = head_free & !joins, single = false;
    else
      settled += tail_free & !joins;
    tail_free = light & !joins;
  }
  // add() for bodies 1 .. n - 1 of a run (n >= 2) after its body 0: the pairs
  // (0, 1) and (n - 2, n - 1) join first_joins and last_joins, `lone` of bodies
  // 1 .. n - 2 are lone and light, body n - 1 is light or not.
  void add_run(bool first_joins, std::size_t lone, bool last_joins, bool last_light) {
    add(first_joins, last_light);  // body 0 settled; body 1, unless the last, is among `lone`
    settled += lone;
    tail_free = last_light & !last_joins;
  }
  // The lone light bodies, the ends settled by the pairs across the cuts:
  // left_joins into the first body, right_joins out of the last (false where
  // there is no pair: the ends of a line). An empty stretch has none.
  std::size_t with_cuts(bool left_joins, bool right_joins) const {
    if (single) return head_free && !left_joins && !right_joins;
    return settled + (head_free && !left_joins) + (tail_free && !right_joins);
  }
};

}  // namespace shockgas::particles::detail
