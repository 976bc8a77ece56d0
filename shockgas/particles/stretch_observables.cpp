#include "shockgas/particles/stretch_observables.hpp"

#include <algorithm>

namespace shockgas::particles::detail {

bool out_of_order(const ClusterPart& part, const SampleSpec& spec) {
  if (part.drops == 0) return false;
  return part.drops > 1 || !spec.ring || !(part.max_drop > 0.5 * spec.L);
}

ClusterPart sorted_part(std::vector<std::pair<double, double>> wv, std::size_t first_index,
                        std::size_t last_index, const SampleSpec& spec) {
  std::size_t seam = 0;  // first body after the seam
  if (spec.ring) {
    double largest = 0;
    for (std::size_t k = 1; k < wv.size(); ++k)
      if (wv[k - 1].first - wv[k].first > largest) largest = wv[k - 1].first - wv[k].first, seam = k;
    if (!(largest > 0.5 * spec.L)) seam = 0;
  }
  auto by_w = [](const std::pair<double, double>& a, const std::pair<double, double>& b) {
    return a.first < b.first;
  };
  const auto cut = wv.begin() + static_cast<std::ptrdiff_t>(seam);
  std::stable_sort(wv.begin(), cut, by_w);
  std::stable_sort(cut, wv.end(), by_w);
  ClusterScan scan(spec);
  for (const auto& [w, v] : wv) scan.add(w, v, 0, false);
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

// Each pair inside a part is counted there; here the pairs across the cuts (on
// a ring also the last part's last body with the first part's first), then the
// rule of ClusterCounter::count.
ClusterCount count_clusters(const std::vector<const ClusterPart*>& parts, std::size_t bodies,
                            const SampleSpec& spec) {
  if (spec.ring && bodies < 2) return {bodies, true};
  const double L = spec.ring ? spec.L : 0.0;
  std::size_t joined = 0, drops = 0;
  int counted = -1, wrapped = -1;  // the closing pair's joins
  for (const ClusterPart* p : parts) {
    joined += p->joined, drops += p->drops;
    if (p->closing_counted >= 0) counted = p->closing_counted, wrapped = p->closing_wrapped;
  }
  const std::size_t cuts = spec.ring ? parts.size() : parts.size() - 1;
  for (std::size_t k = 0; k < cuts; ++k) {
    const ClusterPart& l = *parts[k];
    const ClusterPart& r = *parts[(k + 1) % parts.size()];
    const bool drop = r.first_w < l.last_w;
    const double gap = drop ? (r.first_w + L) - l.last_w : r.first_w - l.last_w;
    const bool join = spec.criteria.joins(gap, r.first_v - l.last_v);
    joined += join, drops += drop;
    if (spec.ring && r.first_index < l.last_index)
      counted = join, wrapped = spec.criteria.joins((r.first_w + L) - l.last_w, r.first_v - l.last_v);
  }
  if (!spec.ring) return {bodies - joined, drops == 0};
  if (drops == 0 && counted >= 0)
    joined = joined - static_cast<std::size_t>(counted) + static_cast<std::size_t>(wrapped);
  return {joined < bodies ? bodies - joined : 1, drops <= 1};
}

}  // namespace shockgas::particles::detail
