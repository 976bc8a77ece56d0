#pragma once
// The particle realizations a run computes and which process computes which.
// A scene is one ensemble, a sweep one per variant; ensemble e has R_e =
// particles.realizations realizations, indexed 0..R_e-1, whose seeds depend on
// their index only. A shard computes a slice of the indices of each ensemble
// (and may take only some variants); an MPI job deals the work items out to
// its ranks. Whoever computes a realization, the records come back to one place
// and each ensemble is reduced in index order (reduce_ensemble_records).
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "shockgas/app/records/realization_record.hpp"
#include "shockgas/app/scene/scene.hpp"
#include "shockgas/core/initial_condition.hpp"
#include "shockgas/particles/simulate.hpp"

namespace shockgas::app {

// A half-open range of indices [begin, end), written "begin:end".
struct Slice {
  std::uint64_t begin = 0, end = 0;
  bool operator==(const Slice&) const = default;
};
std::string slice_text(const Slice& s);
// Reads "A:B" (0 <= A < B); InputError naming `option` otherwise.
Slice parse_slice(const std::string& text, const std::string& option);
// The same, "" for no slice (all of them), as --realizations and --variants are given.
std::optional<Slice> parse_optional_slice(const std::string& text, const std::string& option);

struct WorkItem {
  std::size_t ensemble = 0;  // the variant of a sweep; 0 otherwise
  std::uint64_t index = 0;   // the realization
  bool operator==(const WorkItem&) const = default;
};

class EnsemblePlan {
 public:
  // Every ensemble of `scene` (each variant parsed, its initial condition built
  // and its preflight done: InputError before any work). realizations: the
  // slice computed here of each ensemble (nullopt: all); variants: the slice of
  // a sweep's variants computed here (nullopt: all).
  EnsemblePlan(const Scene& scene, std::optional<Slice> realizations, std::optional<Slice> variants);

  std::size_t ensembles() const { return parts_.size(); }  // every variant, computed here or not
  const Scene& scene(std::size_t e) const { return parts_[e].scene; }
  const InitialCondition& initial(std::size_t e) const;  // only for an ensemble computed here
  std::uint64_t realizations(std::size_t e) const { return parts_[e].scene.particles.realizations; }
  const std::optional<Slice>& realization_slice() const { return realization_slice_; }
  const std::optional<Slice>& variant_slice() const { return variant_slice_; }

  // The items computed here, realization-major (0 of every ensemble, then 1, ...)
  // so that a deal spreads the variants too.
  const std::vector<WorkItem>& items() const { return items_; }
  // Rank `rank`'s items of a job of `ranks`: deal(items(), rank, ranks).
  std::vector<WorkItem> share(int rank, int ranks) const;
  // "realization 3" or "realization 3 of variant 'r = 0.5'", for messages.
  std::string describe(const WorkItem& item) const;

 private:
  struct Part {
    Scene scene;
    std::optional<InitialCondition> initial;  // built where the ensemble is computed
  };
  std::vector<Part> parts_;
  std::optional<Slice> realization_slice_, variant_slice_;
  std::vector<WorkItem> items_;
  bool sweep_ = false;
  std::string scene_name_;
};

// Rank `rank`'s items of `items` dealt out to `ranks` ranks: every ranks-th
// item from the rank-th.
std::vector<WorkItem> deal(const std::vector<WorkItem>& items, int rank, int ranks);

// Ensemble e from the records of all its realizations (any order, each index
// 0..R_e-1 once): particles::reduce_ensemble on them in index order. RunError
// naming the missing or repeated index otherwise.
particles::EnsembleResult reduce_ensemble_records(std::vector<RealizationRecord> records,
                                                  std::uint64_t realizations);

}  // namespace shockgas::app
