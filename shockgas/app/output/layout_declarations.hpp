#pragma once
// Helpers for the declarations of the output layout (declaration.hpp), and the
// declaration lists of each file: output_datasets.cpp (provenance, initial,
// particles), output_fields.cpp (analysis, continuum, comparison, sweep),
// summary_keys.cpp, summary_fields.cpp, output_frames.cpp (frames), summary_extremes.cpp.
#include <functional>
#include <string>
#include <vector>

#include "shockgas/app/output/declaration.hpp"
#include "shockgas/compare/theory_scope.hpp"

namespace shockgas::app::layout {

using Emit = std::function<void(const RunResults&, Emitter&)>;

inline Declaration dataset(Part part, std::string path, std::string unit, std::string description,
                           std::string when, Emit emit) {
  return {{LayoutEntry::Kind::dataset, part, std::move(path), std::move(unit), std::move(description),
           std::move(when)},
          std::move(emit)};
}

inline Declaration attribute(Part part, std::string path, std::string unit, std::string description,
                             std::string when, Emit emit) {
  return {{LayoutEntry::Kind::attribute, part, std::move(path), std::move(unit), std::move(description),
           std::move(when)},
          std::move(emit)};
}

inline Declaration key(Part part, std::string path, std::string unit, std::string description,
                       std::string when, Emit emit) {
  return {{LayoutEntry::Kind::summary, part, std::move(path), std::move(unit), std::move(description),
           std::move(when)},
          std::move(emit)};
}

// d with what the law says its value should be (LayoutEntry::theory).
inline Declaration with_theory(Declaration d, compare::Law law, std::string value) {
  d.entry.theory.push_back({compare::declaration(law).id, std::move(value)});
  return d;
}

// d with what its numerics give wherever it is written ("0 to rounding").
inline Declaration with_exact_value(Declaration d, std::string value) {
  d.entry.theory.push_back({"", std::move(value)});
  return d;
}

// d, a dataset, stored as `storage` (storage.hpp): float32 for data that are
// only drawn, integer for counts, indices and masks.
inline Declaration stored_as(Storage storage, Declaration d) {
  d.entry.storage = storage;
  return d;
}

// Appends b to a.
inline void append(std::vector<Declaration>& a, std::vector<Declaration> b) {
  for (auto& d : b) a.push_back(std::move(d));
}

std::vector<Declaration> provenance_datasets();
std::vector<Declaration> particle_datasets();  // with the initial condition's
std::vector<Declaration> field_datasets();     // analysis, continuum, comparison, sweep

std::vector<Declaration> run_keys();                // provenance, initial, particles, analysis
std::vector<Declaration> theory_keys();             // theory_scopes.cpp: theory.<id>, one per law
std::vector<Declaration> realization_datasets();    // output_realizations.cpp: each realization's series
std::vector<Declaration> realization_error_keys();  // ... and the analysis' errors from them
std::vector<Declaration> comparison_keys();         // continuum, comparison, sweep

std::vector<Declaration> frame_datasets();  // output_frames.cpp: the animation's record
std::vector<Declaration> frame_keys();      // and the wave's evolution
std::vector<Declaration> extreme_keys();    // summary_extremes.cpp: the heaviest shock and cluster, ...
std::vector<Declaration> shard_datasets();  // output_shard.cpp
std::vector<Declaration> shard_keys();

}  // namespace shockgas::app::layout
