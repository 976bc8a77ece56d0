#pragma once
// The resource preflight of `shockgas tail` (studies/tail_study.hpp), in the
// terms of resources.hpp: the memory, the threads and the disk a study needs,
// estimated from its options before anything is allocated or made.
#include <filesystem>

#include "shockgas/app/run/resources.hpp"
#include "shockgas/studies/tail_study.hpp"

namespace shockgas::app {

// Peak memory: one realization at work per thread (its bodies and the hull or
// the event engine that advances them, its states at the times), every
// realization's temperatures, and the histograms (each thread's, and the
// jackknife's groups).
ResourceEstimate estimate_tail_memory(const studies::TailStudyOptions& options);

// Refuses a study that does not fit (memory, threads: InputError naming the
// option that needs most, as tail.N, tail.realizations, tail.threads,
// tail.bin_width; disk: naming --out).
void check_tail_resources(const studies::TailStudyOptions& options);

}  // namespace shockgas::app
