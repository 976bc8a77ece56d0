#pragma once
// What an ensemble keeps of one realization, as named arrays of numbers: the one
// form in which a realization's result is sent between MPI ranks, stored in a
// shard and read back for a merge (and saved with a checkpoint), so that every
// path hands particles::reduce_ensemble the same numbers, bit for bit.
//
// A record holds the time series, the histogram, the final clusters (when
// recorded), how the run ended and its collisions; the record of realization 0
// also holds its states (final state, snapshots, space-time record), which the
// other realizations never carry (strip_states).
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "shockgas/particles/run_result.hpp"

namespace shockgas::app {

// Named arrays: "series/T", "stop", "final/x", "snapshots/0/x", ...
using RecordFields = std::vector<std::pair<std::string, std::vector<double>>>;

// Realization `index` of ensemble `ensemble` (a sweep's variant; 0 for a scene
// without sweep).
struct RealizationRecord {
  std::uint64_t ensemble = 0;
  std::uint64_t index = 0;
  particles::RunResult run;
  // Realization 0 whose snapshots and final state went to its state file
  // (state_file.hpp) as it ran: run holds none of them.
  bool states_apart = false;
};

// Drops the states that only realization 0 keeps.
void strip_states(particles::RunResult& run);

// The fields of a run, every number exactly (integers as exact doubles: the
// collision count split into two 32-bit halves).
RecordFields to_fields(const particles::RunResult& run);
// The inverse of to_fields; RunError naming the field when one is missing or malformed.
particles::RunResult from_fields(const RecordFields& fields);

// A record as bytes (for a message, a checkpoint) and back, states_apart with
// it; RunError on a malformed buffer.
std::string encode(const RealizationRecord& record);
RealizationRecord decode(const std::string& bytes);

}  // namespace shockgas::app
