#include "shockgas/compare/matching.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>

#include "shockgas/core/error.hpp"

namespace shockgas::compare {

double periodic_displacement(double a, double b, double L) {
  double d = std::fmod(b - a, L);
  if (d < -0.5 * L) d += L;
  if (d >= 0.5 * L) d -= L;
  return d;
}

namespace {

struct Candidate {
  double distance;  // |periodic displacement|
  std::size_t shock, cluster;
};

// Eligible clusters sorted by x, as (x, index).
std::vector<std::pair<double, std::size_t>> sorted_positions(const std::vector<particles::Cluster>& clusters,
                                                             double min_mass) {
  std::vector<std::pair<double, std::size_t>> sorted;
  for (std::size_t j = 0; j < clusters.size(); ++j)
    if (clusters[j].m >= min_mass) sorted.emplace_back(clusters[j].x, j);
  std::sort(sorted.begin(), sorted.end());
  return sorted;
}

// All (shock, cluster) pairs within max_distance, by a binary search around
// each shock in the sorted clusters (and its images at x +- L).
std::vector<Candidate> candidate_pairs(const std::vector<continuum::Shock>& shocks,
                                       const std::vector<particles::Cluster>& clusters, double L,
                                       const MatchParams& p) {
  const auto sorted = sorted_positions(clusters, p.min_mass);
  std::vector<Candidate> out;
  for (std::size_t i = 0; i < shocks.size(); ++i) {
    if (shocks[i].mass < p.min_mass) continue;
    std::vector<std::size_t> seen;
    for (double image : {-L, 0.0, L}) {
      const double lo = shocks[i].x + image - p.max_distance, hi = shocks[i].x + image + p.max_distance;
      auto it = std::lower_bound(sorted.begin(), sorted.end(), std::make_pair(lo, std::size_t{0}));
      for (; it != sorted.end() && it->first <= hi; ++it) {
        if (std::find(seen.begin(), seen.end(), it->second) != seen.end()) continue;
        seen.push_back(it->second);
        const double d = std::abs(periodic_displacement(shocks[i].x, it->first, L));
        if (d <= p.max_distance) out.push_back(Candidate{d, i, it->second});
      }
    }
  }
  std::sort(out.begin(), out.end(), [](const Candidate& a, const Candidate& b) {
    return std::tie(a.distance, a.shock, a.cluster) < std::tie(b.distance, b.shock, b.cluster);
  });
  return out;
}

// A quarter of the mean spacing of the eligible shocks.
double automatic_distance(const std::vector<continuum::Shock>& shocks, double L, const MatchParams& p) {
  std::size_t n = 0;
  for (const auto& s : shocks) n += s.mass >= p.min_mass ? 1 : 0;
  return L / (4.0 * static_cast<double>(std::max<std::size_t>(n, 1)));
}

void summarise(MatchResult& r, const std::vector<continuum::Shock>& shocks,
               const std::vector<particles::Cluster>& clusters, double min_mass) {
  std::vector<bool> shock_used(shocks.size(), false), cluster_used(clusters.size(), false);
  double sum_dx2 = 0, sum_dv2 = 0;
  for (const MatchedPair& pair : r.pairs) {
    shock_used[pair.shock] = cluster_used[pair.cluster] = true;
    r.matched_cluster_mass += clusters[pair.cluster].m;
    r.max_position_error = std::max(r.max_position_error, std::abs(pair.position_error));
    r.max_relative_mass_error =
        std::max(r.max_relative_mass_error, std::abs(pair.mass_error) / clusters[pair.cluster].m);
    sum_dx2 += pair.position_error * pair.position_error;
    sum_dv2 += pair.velocity_error * pair.velocity_error;
  }
  for (std::size_t i = 0; i < shocks.size(); ++i) {
    if (shocks[i].mass < min_mass) continue;
    ++r.eligible_shocks;
    if (!shock_used[i]) r.unmatched_shocks.push_back(i);
  }
  for (std::size_t j = 0; j < clusters.size(); ++j) {
    if (clusters[j].m < min_mass) continue;
    ++r.eligible_clusters;
    r.cluster_mass += clusters[j].m;
    if (!cluster_used[j]) r.unmatched_clusters.push_back(j);
  }
  r.matched_mass_fraction = r.cluster_mass > 0 ? r.matched_cluster_mass / r.cluster_mass : 0.0;
  if (!r.pairs.empty()) {
    const double n = static_cast<double>(r.pairs.size());
    r.rms_position_error = std::sqrt(sum_dx2 / n);
    r.rms_velocity_error = std::sqrt(sum_dv2 / n);
  }
}

}  // namespace

MatchResult match_shocks_to_clusters(const std::vector<continuum::Shock>& shocks,
                                     const std::vector<particles::Cluster>& clusters, double L,
                                     const MatchParams& params) {
  require(std::isfinite(L) && L > 0, "compare.L", L, "> 0");
  require(std::isfinite(params.max_distance) && params.max_distance >= 0, "compare.match_distance",
          params.max_distance, "a finite number >= 0 (0 = automatic)");
  require(std::isfinite(params.min_mass) && params.min_mass >= 0, "compare.min_cluster_particles",
          params.min_mass, "a finite mass >= 0 (min_cluster_particles times the mean particle mass)");
  const MatchParams used{
      params.max_distance > 0 ? params.max_distance : automatic_distance(shocks, L, params), params.min_mass};
  std::vector<bool> shock_taken(shocks.size(), false), cluster_taken(clusters.size(), false);
  MatchResult r;
  r.max_distance = used.max_distance;
  for (const Candidate& c : candidate_pairs(shocks, clusters, L, used)) {
    if (shock_taken[c.shock] || cluster_taken[c.cluster]) continue;
    shock_taken[c.shock] = cluster_taken[c.cluster] = true;
    const auto& s = shocks[c.shock];
    const auto& k = clusters[c.cluster];
    r.pairs.push_back(
        MatchedPair{c.shock, c.cluster, periodic_displacement(s.x, k.x, L), k.m - s.mass, k.v - s.v});
  }
  std::sort(r.pairs.begin(), r.pairs.end(), [](const auto& a, const auto& b) { return a.shock < b.shock; });
  summarise(r, shocks, clusters, params.min_mass);
  return r;
}

}  // namespace shockgas::compare
