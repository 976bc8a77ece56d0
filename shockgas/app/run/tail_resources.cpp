#include "shockgas/app/run/tail_resources.hpp"

#include <algorithm>
#include <cmath>

#include "shockgas/app/directory/run_target.hpp"
#include "shockgas/app/files/durable_file.hpp"
#include "shockgas/core/cores.hpp"
#include "shockgas/particles/simulate.hpp"

namespace shockgas::app {

namespace {

// Measured (N = 10^6 and 4 x 10^6, r = 0, one thread: 29.9 bytes per body
// at the peak, the hull built while the initial bodies are held), held above.
constexpr double kHullBodyBytes = 40;
// A realization's temperatures: a vector of one value per time (measured
// with the heap's own overhead: about 56 bytes for three times).
constexpr double kRealizationBytes = 64, kTimeBytes = 8;
constexpr double kBinBytes = 16;   // mass and clusters per bin
constexpr double kRowBytes = 200;  // a row of tail_phi.csv (11 numbers)

double d(std::size_t n) { return static_cast<double>(n); }

std::size_t threads_of(const studies::TailStudyOptions& o) {
  return o.threads == 0 ? usable_cores() : o.threads;
}

double bins_of(const studies::TailStudyOptions& o) { return std::ceil(o.z_max / o.bin_width); }

InputError refusal(const studies::TailStudyOptions& o, const std::string& key, const std::string& allowed) {
  if (key == "tail.realizations") return InputError(key, to_text(o.realizations), allowed);
  if (key == "tail.threads") return InputError(key, to_text(o.threads), allowed);
  if (key == "tail.bin_width") return InputError(key, to_text(o.bin_width), allowed);
  if (key == "tail.times") return InputError(key, to_text(o.times.size()), allowed);
  return InputError("tail.N", to_text(*std::max_element(o.sizes.begin(), o.sizes.end())), allowed);
}

}  // namespace

ResourceEstimate estimate_tail_memory(const studies::TailStudyOptions& o) {
  const double N = d(*std::max_element(o.sizes.begin(), o.sizes.end())), times = d(o.times.size());
  const double at_once = d(std::min<std::size_t>(threads_of(o), o.realizations));
  double body = kHullBodyBytes;
  if (o.r > 0) {  // the event engine of one thread, its states at the times kept
    particles::ParticleParams p;
    p.r = o.r, p.delta = o.delta, p.threads = 1;
    body = kBodyBytes + particles::bytes_per_body(p, true) + times * kBodyBytes;
  }
  ResourceEstimate e;
  e.items.push_back({"", "the program and its libraries", kProcessBaseBytes});
  e.items.push_back(
      {"tail.N", "the realizations at work, one per thread", at_once * N * body, {"tail.threads"}});
  e.items.push_back({"tail.realizations",
                     "the temperatures of every realization",
                     d(o.realizations) * (kRealizationBytes + times * kTimeBytes),
                     {"tail.times"}});
  e.items.push_back({"tail.bin_width",
                     "the histograms of the threads and of the jackknife's groups",
                     (at_once + d(studies::kTailJackknifeGroups)) * times * bins_of(o) * kBinBytes,
                     {"tail.times"}});
  return e;
}

void check_tail_resources(const studies::TailStudyOptions& o) {
  require_threads(o.threads, [&](const std::string& allowed) { return refusal(o, "tail.threads", allowed); });
  const ResourceEstimate memory = estimate_tail_memory(o);
  require_memory(memory, "a study",
                 [&](const std::string& allowed) { return refusal(o, memory.largest().key, allowed); });
  const double rows = d(o.sizes.size()) * d(o.times.size()) * bins_of(o) * 2;  // the data's and the law's
  const double free = static_cast<double>(free_bytes(resolve_target(o.out_dir)));
  if (rows * kRowBytes > free)
    throw InputError("--out", to_text(o.out_dir),
                     "a file system with room for the tables: they need about " +
                         size_text(rows * kRowBytes) + ", " + size_text(free) + " free");
}

}  // namespace shockgas::app
