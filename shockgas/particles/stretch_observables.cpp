#include "shockgas/particles/stretch_observables.hpp"

#include <algorithm>

namespace shockgas::particles::detail {

bool out_of_order(const ClusterPart& part, const SampleSpec& spec) {
  if (part.drops == 0) return false;
  return part.drops > 1 || !spec.ring || !(part.max_drop > 0.5 * spec.L);
}

ClusterPart sorted_part(std::vector<ScanBody> bodies, std::size_t first_index, std::size_t last_index,
                        const SampleSpec& spec) {
  std::size_t seam = 0;  // first body after the seam
  if (spec.ring) {
    double largest = 0;
    for (std::size_t k = 1; k < bodies.size(); ++k)
      if (bodies[k - 1].w - bodies[k].w > largest) largest = bodies[k - 1].w - bodies[k].w, seam = k;
    if (!(largest > 0.5 * spec.L)) seam = 0;
  }
  auto by_w = [](const ScanBody& a, const ScanBody& b) { return a.w < b.w; };
  const auto cut = bodies.begin() + static_cast<std::ptrdiff_t>(seam);
  std::stable_sort(bodies.begin(), cut, by_w);
  std::stable_sort(cut, bodies.end(), by_w);
  ClusterScan scan(spec);
  for (const ScanBody& b : bodies) scan.add(b.w, b.v, b.m, 0, false);
  ClusterPart part = scan.part();
  part.first_index = first_index, part.last_index = last_index;
  return part;
}

SampleMoments combine_moments(const StretchPart* parts, std::size_t count, std::size_t stride) {
  SampleMoments s;
  for (std::size_t k = 0; k < count; ++k) {
    const StretchPart& p = parts[k * stride];
    s.mass += p.mass, s.momentum += p.momentum, s.bodies += p.bodies;
  }
  const double mean = s.momentum / s.mass;
  double spread = 0;
  for (std::size_t k = 0; k < count; ++k) {
    const StretchPart& p = parts[k * stride];
    const double shift = p.momentum / p.mass - mean;
    spread += p.spread + p.mass * shift * shift;
  }
  s.T = spread / s.mass;
  return s;
}

namespace {

// The lone light bodies of the parts: each part's ends settled by the pairs
// across its cuts (cut_joins[k]: between parts k and k + 1; a line's ends have
// none), a part with the closing pair inside on both sides of it (closing_joins).
std::size_t lone_bodies(const std::vector<const ClusterPart*>& parts, const std::vector<char>& cut_joins,
                        bool closing_joins, bool ring) {
  std::size_t lone = 0;
  for (std::size_t k = 0; k < parts.size(); ++k) {
    const bool left = k > 0 ? cut_joins[k - 1] : ring && cut_joins.back();
    const bool right = k < cut_joins.size() && cut_joins[k];
    const ClusterPart& p = *parts[k];
    if (p.closing_counted >= 0)
      lone += p.before_closing.with_cuts(left, closing_joins) + p.lone.with_cuts(closing_joins, right);
    else
      lone += p.lone.with_cuts(left, right);
  }
  return lone;
}

}  // namespace

// Each pair inside a part is counted there; here the pairs across the cuts (on
// a ring also the last part's last body with the first part's first), then the
// rule of ClusterCounter::count.
ClusterCount count_clusters(const std::vector<const ClusterPart*>& parts, std::size_t bodies,
                            const SampleSpec& spec) {
  const bool ring = spec.ring;
  if (ring && bodies < 2) {  // one body holds every particle: it counts if heavy
    std::size_t lone = 0;
    for (const ClusterPart* p : parts) lone += p->lone.with_cuts(false, false);
    return {bodies - lone, true};
  }
  const double L = ring ? spec.L : 0.0;
  std::size_t joined = 0, drops = 0;
  int counted = -1, wrapped = -1;          // the closing pair's joins
  std::size_t closing_cut = parts.size();  // the cut that is the closing pair, if one is
  for (const ClusterPart* p : parts) {
    joined += p->joined, drops += p->drops;
    if (p->closing_counted >= 0) counted = p->closing_counted, wrapped = p->closing_wrapped;
  }
  std::vector<char> cut_joins(ring ? parts.size() : parts.size() - 1);
  for (std::size_t k = 0; k < cut_joins.size(); ++k) {
    const ClusterPart& l = *parts[k];
    const ClusterPart& r = *parts[(k + 1) % parts.size()];
    const bool drop = r.first_w < l.last_w;
    const double gap = drop ? (r.first_w + L) - l.last_w : r.first_w - l.last_w;
    const bool join = spec.criteria.joins(gap, r.first_v - l.last_v);
    joined += join, drops += drop, cut_joins[k] = join;
    if (ring && r.first_index < l.last_index) {
      counted = join, wrapped = spec.criteria.joins((r.first_w + L) - l.last_w, r.first_v - l.last_v);
      closing_cut = k;
    }
  }
  if (!ring) return {bodies - joined - lone_bodies(parts, cut_joins, false, false), drops == 0};
  const bool across_wrap = drops == 0 && counted >= 0;  // the closing pair is the wrapping one
  if (across_wrap) {
    joined = joined - static_cast<std::size_t>(counted) + static_cast<std::size_t>(wrapped);
    if (closing_cut < cut_joins.size()) cut_joins[closing_cut] = static_cast<char>(wrapped);
  }
  const std::size_t clusters = joined < bodies ? bodies - joined : 1;
  return {clusters - lone_bodies(parts, cut_joins, across_wrap ? wrapped == 1 : counted == 1, true),
          drops <= 1};
}

}  // namespace shockgas::particles::detail
