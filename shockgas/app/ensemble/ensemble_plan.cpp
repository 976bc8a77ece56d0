#include "shockgas/app/ensemble/ensemble_plan.hpp"

#include <algorithm>

#include "shockgas/app/input/scene_parser.hpp"
#include "shockgas/app/run/run_internal.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::app {

std::string slice_text(const Slice& s) { return std::to_string(s.begin) + ":" + std::to_string(s.end); }

Slice parse_slice(const std::string& text, const std::string& option) {
  const std::string allowed = "A:B, whole numbers with 0 <= A < B (the indices A..B-1)";
  const auto colon = text.find(':');
  auto number = [&](const std::string& part) -> std::uint64_t {
    if (part.empty() || part.find_first_not_of("0123456789") != std::string::npos || part.size() > 18)
      throw InputError(option, to_text(text), allowed);
    return std::stoull(part);
  };
  if (colon == std::string::npos) throw InputError(option, to_text(text), allowed);
  const Slice s{number(text.substr(0, colon)), number(text.substr(colon + 1))};
  require(s.begin < s.end, option, text, allowed);
  return s;
}

std::optional<Slice> parse_optional_slice(const std::string& text, const std::string& option) {
  return text.empty() ? std::nullopt : std::optional(parse_slice(text, option));
}

EnsemblePlan::EnsemblePlan(const Scene& scene, std::optional<Slice> realizations,
                           std::optional<Slice> variants)
    : realization_slice_(realizations),
      variant_slice_(variants),
      sweep_(scene.has_sweep),
      scene_name_(scene.name) {
  if (variants && !scene.has_sweep)
    throw InputError("--variants", to_text(slice_text(*variants)),
                     "a scene with [sweep] (this one has none)");
  std::vector<Scene> scenes = scene.has_sweep ? expand_sweep(scene) : std::vector<Scene>{scene};
  const Slice all_variants{0, scenes.size()};
  const Slice chosen = variants.value_or(all_variants);
  if (chosen.end > scenes.size())
    throw InputError("--variants", to_text(slice_text(chosen)),
                     "a slice of the sweep's " + std::to_string(scenes.size()) +
                         " variants, end <= " + std::to_string(scenes.size()));
  for (std::size_t e = 0; e < scenes.size(); ++e) {
    Part part{std::move(scenes[e]), std::nullopt};
    const bool here = e >= chosen.begin && e < chosen.end;
    if (here) {
      part.initial.emplace(build_initial(part.scene));
      preflight(part.scene, *part.initial);
    }
    if (here && realizations && !part.scene.has_particles)
      throw InputError("--realizations", to_text(slice_text(*realizations)),
                       "a scene with [particles] (" + part.scene.name + " runs no particles)");
    if (here && realizations && realizations->end > part.scene.particles.realizations)
      throw InputError(
          "--realizations", to_text(slice_text(*realizations)),
          "a slice of particles.realizations = " + std::to_string(part.scene.particles.realizations) +
              " of " + part.scene.name + ": end <= " + std::to_string(part.scene.particles.realizations));
    parts_.push_back(std::move(part));
  }
  std::uint64_t most = 0;
  for (const Part& p : parts_) most = std::max<std::uint64_t>(most, p.scene.particles.realizations);
  for (std::uint64_t k = 0; k < most; ++k)
    for (std::size_t e = chosen.begin; e < chosen.end; ++e) {
      const Part& p = parts_[e];
      const Slice slice = realizations.value_or(Slice{0, p.scene.particles.realizations});
      if (p.scene.has_particles && k >= slice.begin && k < slice.end) items_.push_back({e, k});
    }
}

const InitialCondition& EnsemblePlan::initial(std::size_t e) const {
  if (!parts_[e].initial) throw RunError("ensemble " + std::to_string(e) + " is not computed here");
  return *parts_[e].initial;
}

std::vector<WorkItem> EnsemblePlan::share(int rank, int ranks) const { return deal(items_, rank, ranks); }

std::vector<WorkItem> deal(const std::vector<WorkItem>& items, int rank, int ranks) {
  std::vector<WorkItem> mine;
  for (std::size_t i = static_cast<std::size_t>(rank); i < items.size(); i += static_cast<std::size_t>(ranks))
    mine.push_back(items[i]);
  return mine;
}

std::string EnsemblePlan::describe(const WorkItem& item) const {
  std::string text = "realization " + std::to_string(item.index);
  if (sweep_) text += " of variant '" + parts_[item.ensemble].scene.name.substr(scene_name_.size() + 1) + "'";
  return text;
}

particles::EnsembleResult reduce_ensemble_records(std::vector<RealizationRecord> records,
                                                  std::uint64_t realizations) {
  std::sort(records.begin(), records.end(),
            [](const RealizationRecord& a, const RealizationRecord& b) { return a.index < b.index; });
  std::vector<particles::RunResult> runs;
  runs.reserve(records.size());
  for (auto& r : records) {
    if (r.index != runs.size())
      throw RunError("realization " + std::to_string(runs.size()) +
                     (r.index < runs.size() ? " came twice" : " is missing"));
    runs.push_back(std::move(r.run));
  }
  if (runs.size() != realizations)
    throw RunError("realization " + std::to_string(runs.size()) + " is missing");
  return particles::reduce_ensemble(std::move(runs));
}

}  // namespace shockgas::app
