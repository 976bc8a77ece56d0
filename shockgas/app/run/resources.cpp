// The resource preflight (resources.hpp): the estimate, item by item, and the
// limits of the process.
#include "shockgas/app/run/resources.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "shockgas/app/directory/run_target.hpp"
#include "shockgas/app/files/durable_file.hpp"
#include "shockgas/app/input/scene_parser.hpp"
#include "shockgas/app/records/state_file.hpp"
#include "shockgas/app/scene/scene_schema.hpp"
#include "shockgas/continuum/registry.hpp"
#include "shockgas/core/cores.hpp"
#include "shockgas/core/error.hpp"
#include "shockgas/core/initial_stream.hpp"
#include "shockgas/particles/simulate.hpp"

namespace shockgas::app {

namespace fs = std::filesystem;

namespace {

// Measured costs (tests/app/test_resources.cpp holds the total against the peak
// resident memory of real runs):
// Copies of the records held at the peak (measured with threads = 1): a
// histogram 2R + 3 times (each realization's, kept and written with the
// ensemble's, scaled and written: 5.0 at R = 1), a space-time record R + 1
// times (1.2 at R = 1, 2.8 at R = 2).
constexpr double kHistogramCopies = 3, kSpacetimeCopies = 1;
constexpr double kCellResultBytes = 24;  // x, v, rho kept per cell and solver
constexpr double kSeriesColumns = 10;    // the time series of a run (run_result.hpp)
// On disk (tests/app/test_resources.cpp holds the total against the bytes real
// runs wrote and against their values uncompressed): every value uncompressed,
// as float64, an upper bound of what result.h5 stores (layout 2.0 deflates the
// values and keeps some as float32 or integers: 2.5 to 3.4 times fewer bytes
// in that test's runs, depending on the values); result.h5's metadata and
// attributes (55 kB at the default scene), summary.json, report.md and report.html without pictures (30 kB),
// and the model's shortfalls elsewhere (the default scene at 2000 cells wrote
// 110 kB beyond its other items); the cells
// of the initial condition (x, v, rho) and of the comparison (x, v, rho,
// occupied); the PNG plots (0.72 MB at the default scene, counted as 0.9 MB:
// busier data make larger pictures), which report.html embeds again in base64
// (4/3 of their bytes).
constexpr double kFileOverhead = 0.2e6;
constexpr double kInitialCellBytes = 24, kCompareCellBytes = 32;
constexpr double kPlotsBytes = 0.9e6 * (1 + 4.0 / 3);

double d(std::size_t n) { return static_cast<double>(n); }

// The columns of the space-time record (particles/run_result.hpp: spacetime_labels).
double recorded_world_lines(const Scene& s) {
  return d(std::min<std::size_t>(s.initial.N, s.particles.spacetime_particles));
}

// The realizations that run at once: the ensemble's own split of the threads.
std::size_t concurrent_runs(const particles::ParticleParams& p) {
  return particles::split_threads(p.threads == 0 ? usable_cores() : p.threads, p.realizations).runs;
}

// What a run of one scene (no sweep) holds at its peak. Realization 0's
// snapshots and final state stream to the output directory (state_file.hpp);
// the other realizations keep no states.
void particle_memory(const Scene& s, std::vector<ResourceItem>& items) {
  const auto& p = s.particles;
  const double N = d(s.initial.N), R = d(p.realizations), samples = d(p.samples);
  // Realization 0's bodies are held only for a continuum, or when they cannot be drawn in chunks (run.cpp);
  // bodies that are not drawn may have unequal masses.
  const bool drawn = InitialStream::streamable(s.initial);
  const double initial = s.has_continuum || !drawn ? kBodyBytes : 0;
  items.push_back({"initial.N",
                   "the particles: the initial condition and the engines at work",
                   N * (initial + d(concurrent_runs(p)) * particles::bytes_per_body(p, drawn)),
                   {"particles.realizations", "particles.threads"}});
  items.push_back({"particles.samples",
                   "the time series of every realization",
                   R * samples * kSeriesColumns * 8,
                   {"particles.realizations"}});
  if (particles::records_final_clusters(p, s.initial.N))
    items.push_back({"particles.final_clusters",
                     "the final clusters of every realization (at most N / 2 each)",
                     particles::final_clusters_bound(p, s.initial.N),
                     {"initial.N", "particles.realizations"}});
  if (p.histogram_bins > 0)
    items.push_back({"particles.histogram_bins",
                     "the velocity histograms of every realization",
                     (2 * R + kHistogramCopies) * samples * d(p.histogram_bins) * 8,
                     {"particles.samples", "particles.realizations"}});
  if (p.spacetime)
    items.push_back({"particles.spacetime",
                     "the space-time records of every realization",
                     (R + kSpacetimeCopies) * d(p.spacetime_frames) * recorded_world_lines(s) * 8,
                     {"particles.spacetime_frames", "particles.spacetime_particles", "initial.N",
                      "particles.realizations"}});
}

// A continuum solver at work, bytes per cell (its registration's measure); a
// solver without one is given the largest.
double solver_cell_bytes(const std::string& solver) {
  double largest = 0;
  for (const auto& info : continuum::registered_solvers()) largest = std::max(largest, info.bytes_per_cell);
  const double own = continuum::solver_info(solver).bytes_per_cell;
  return own > 0 ? own : largest;
}

void continuum_memory(const Scene& s, std::vector<ResourceItem>& items) {
  const double cells = d(s.continuum.cells), solvers = d(s.continuum.solvers.size());
  // Point masses unless the velocities are an expression of x (InitialCondition::from_bodies).
  const double bodies = s.initial.velocities == Velocities::expression ? 0 : d(s.initial.N);
  double at_work = 0, body_work = 0;  // the solvers run one after the other
  for (const auto& solver : s.continuum.solvers) {
    at_work = std::max(at_work, solver_cell_bytes(solver));
    body_work = std::max(body_work, continuum::solver_info(solver).bytes_per_body);
  }
  items.push_back({"continuum.cells",
                   "the continuum solvers: one at work, the fields of each kept",
                   cells * (at_work + solvers * kCellResultBytes),
                   {"continuum.solvers"}});
  if (bodies * body_work > 0)
    items.push_back({"initial.N",
                     "a continuum solver at work on the bodies themselves",
                     bodies * body_work,
                     {"continuum.solvers"}});
}

// The frames of an animation (shockgas/app/output/frames.hpp): the particles (at most N
// clusters) and every solver's fields at each frame time, held and written.
double frame_bytes(const Scene& s) {
  if (!s.output.animation) return 0;
  const double particles = s.has_particles ? d(s.initial.N) * kBodyBytes : 0;
  const double fields =
      s.has_continuum ? d(s.continuum.cells) * d(s.continuum.solvers.size()) * kCellResultBytes : 0;
  return d(s.output.animation_frames) * (particles + fields);
}

std::vector<ResourceItem> single_memory(const Scene& s) {
  std::vector<ResourceItem> items;
  if (s.has_particles) particle_memory(s, items);
  if (s.has_continuum && !s.has_particles)  // the gas's memory counts them otherwise
    items.push_back({"initial.N", "the initial condition's bodies, put on the continuum's grid",
                     d(s.initial.N) * kBodyBytes});
  if (s.has_continuum) continuum_memory(s, items);
  if (s.output.animation)
    items.push_back({"output.animation_frames",
                     "the frames of the animation",
                     frame_bytes(s),
                     {"initial.N", "continuum.cells", "continuum.solvers"}});
  return items;
}

std::vector<ResourceItem> single_disk(const Scene& s, bool plots) {
  std::vector<ResourceItem> items;
  const auto& p = s.particles;
  const double N = d(s.initial.N), samples = d(p.samples);
  if (s.has_particles) {
    // The states result.h5 keeps (output.initial, output.final); the final one has at most N bodies.
    const double final_bodies = s.output.final_state == KeepState::always ? N
                                : s.output.final_state == KeepState::never
                                    ? 0
                                    : std::min(N, d(kStoredStateBodies));
    const double initial_bodies = keeps_state(s.output.initial, s.initial.N) ? N : 0;
    items.push_back({"initial.N", "the initial and final states result.h5 keeps",
                     (initial_bodies + final_bodies) * kBodyBytes});
    items.push_back({"particles.samples", "the time series", samples * 2 * kSeriesColumns * 8});
    if (p.histogram_bins > 0)
      items.push_back({"particles.histogram_bins",
                       "the velocity histogram",
                       samples * d(p.histogram_bins) * 8,
                       {"particles.samples"}});
    if (p.spacetime)
      items.push_back({"particles.spacetime",
                       "the space-time record",
                       d(p.spacetime_frames) * recorded_world_lines(s) * 8,
                       {"particles.spacetime_frames", "particles.spacetime_particles", "initial.N"}});
    if (!p.snapshots.empty())
      items.push_back({"particles.snapshots", "the snapshots", d(p.snapshots.size()) * N * kBodyBytes});
    if (particles::records_final_clusters(p, s.initial.N))
      items.push_back({"particles.final_clusters",
                       "the final clusters of every realization (at most N / 2 each)",
                       particles::final_clusters_bound(p, s.initial.N),
                       {"initial.N", "particles.realizations"}});
    if (keeps_states_apart(s))  // the states result.h5 keeps, and the final state's heaviest cluster
      items.push_back({"initial.N",
                       "realization 0's states in their file beside the results until they are written",
                       (final_bodies + d(p.snapshots.size()) * N + 1) * kBodyBytes});
  }
  const double cells = d(s.continuum.cells);
  if (s.has_continuum)
    items.push_back(
        {"continuum.cells", "the initial condition on the continuum's grid", cells * kInitialCellBytes});
  if (s.has_continuum && s.output.fields)
    items.push_back({"continuum.cells", "the continuum fields",
                     cells * d(s.continuum.solvers.size()) * kCellResultBytes});
  if (s.has_continuum && s.has_compare)
    items.push_back({"continuum.cells", "the particles on the continuum's grid", cells * kCompareCellBytes});
  if (s.output.animation)
    items.push_back({"output.animation_frames", "the frames of the animation", frame_bytes(s)});
  items.push_back({"", "metadata, summary.json, report.md, report.html", kFileOverhead});
  if (plots && s.output.plots)
    items.push_back({"output.plots", "the plots, and again in report.html", kPlotsBytes});
  return items;
}

// A sweep's variants as scenes (their overrides applied), or the scene itself.
std::vector<Scene> runs_of(const Scene& scene) {
  if (!scene.has_sweep) return {scene};
  return expand_sweep(scene);
}

// The key's value as the scene gives it, for the message.
std::string value_of(const Scene& scene, const std::string& dotted) {
  const auto dot = dotted.find('.');
  const TableSpec* table = dot == std::string::npos ? nullptr : find_table(dotted.substr(0, dot));
  const KeySpec* key = table ? table->find(dotted.substr(dot + 1)) : nullptr;
  return key ? key->get(scene).written : "(the scene)";
}

// The key a refusal names: of the keys an item grows with (its own first), one
// the command line or a sweep variant set (the user's change), else one the
// scene gives (not a default), else its own.
std::string blamed_key(const Scene& scene, const ResourceItem& item) {
  auto given = [&](const std::string& key) {
    return key.empty() ? scene.key_origin.end() : scene.key_origin.find(key);
  };
  auto overridden = [&](const std::string& key) {
    const auto it = given(key);
    return it != scene.key_origin.end() &&
           (it->second.rfind("--set ", 0) == 0 || it->second.find("(sweep variant") != std::string::npos);
  };
  auto in_scene = [&](const std::string& key) { return given(key) != scene.key_origin.end(); };
  auto first = [&](const auto& chosen) -> const std::string* {
    if (chosen(item.key)) return &item.key;
    for (const std::string& factor : item.factors)
      if (chosen(factor)) return &factor;
    return nullptr;
  };
  if (const std::string* key = first(overridden)) return *key;
  if (const std::string* key = first(in_scene)) return *key;
  return item.key;
}

// "about NEED (KEY: what, BYTES), ROOM WHERE": the estimate against the room,
// with as many digits as it takes for the two to read differently (a refusal
// that said "2.28 MB ..., 2.28 MB free" named no difference).
std::string estimate_text(const ResourceEstimate& e, double room, const std::string& where) {
  int digits = 3;
  while (digits < 12 && size_text(e.total(), digits) == size_text(room, digits)) ++digits;
  const ResourceItem& big = e.largest();
  std::string keys = big.key;
  for (const std::string& factor : big.factors) keys += " x " + factor;
  return "about " + size_text(e.total(), digits) + " (" + (big.key.empty() ? "" : keys + ": ") + big.what +
         ", " + size_text(big.bytes) + "), " + size_text(room, digits) + " " + where;
}

}  // namespace

double ResourceEstimate::total() const {
  double sum = 0;
  for (const auto& i : items) sum += i.bytes;
  return sum;
}

const ResourceItem& ResourceEstimate::largest() const {
  return *std::max_element(items.begin(), items.end(),
                           [](const auto& a, const auto& b) { return a.bytes < b.bytes; });
}

ResourceEstimate estimate_memory(const Scene& scene) {
  ResourceEstimate e;
  e.items.push_back({"", "the program and its libraries", kProcessBaseBytes});
  const auto runs = runs_of(scene);
  std::vector<ResourceItem> biggest;
  double biggest_total = -1, initial_conditions = 0;
  for (const auto& run : runs) {
    const auto items = single_memory(run);
    double total = 0;
    for (const auto& i : items) total += i.bytes;
    if (total > biggest_total) biggest_total = total, biggest = items;
    if (run.has_particles) initial_conditions += d(run.initial.N) * kBodyBytes;
  }
  for (auto& i : biggest) e.items.push_back(std::move(i));
  if (runs.size() > 1)
    e.items.push_back(
        {"sweep.variants", "the initial conditions of every variant, built up front", initial_conditions});
  return e;
}

ResourceEstimate estimate_disk(const Scene& scene, bool plots) {
  ResourceEstimate e;
  for (const auto& run : runs_of(scene))
    for (auto& i : single_disk(run, plots)) e.items.push_back(std::move(i));
  if (scene.has_sweep)
    e.items.push_back(
        {"", "the sweep's own files", kFileOverhead + (plots && scene.output.plots ? kPlotsBytes : 0)});
  return e;
}

void require_memory(const ResourceEstimate& memory, const std::string& what,
                    const std::function<InputError(const std::string& allowed)>& refusal) {
  const MemoryLimit limit = memory_limit();
  if (memory.total() <= limit.bytes) return;
  throw refusal(what + " that fits in the memory available: it needs " +
                estimate_text(memory, limit.bytes, "available (" + limit.source + ")"));
}

void require_threads(std::size_t threads,
                     const std::function<InputError(const std::string& allowed)>& refusal) {
  const std::size_t cores = usable_cores(), most = kThreadsPerCore * cores;
  if (threads <= most) return;
  throw refusal("0 (one thread per core) or at most " + std::to_string(most) + ": " +
                std::to_string(kThreadsPerCore) + " for each of the " + std::to_string(cores) +
                " cores this process may use (its CPU affinity and quota)");
}

void check_memory(const Scene& scene) {
  const auto located = [&](const std::string& key, const std::string& value, const std::string& allowed) {
    const auto origin = scene.key_origin.find(key);
    return InputError(key.empty() ? "scene" : key, value, allowed,
                      origin != scene.key_origin.end() ? origin->second : scene.path);
  };
  const ResourceEstimate memory = estimate_memory(scene);
  require_memory(memory, "a scene", [&](const std::string& allowed) {
    const std::string key = blamed_key(scene, memory.largest());
    return located(key, value_of(scene, key), allowed);
  });
  for (const Scene& run : runs_of(scene))
    if (run.has_particles)
      require_threads(run.particles.threads, [&](const std::string& allowed) {
        return located("particles.threads", to_text(run.particles.threads), allowed);
      });
}

void check_resources(const Scene& scene, const fs::path& out, bool plots) {
  check_memory(scene);
  const ResourceEstimate disk = estimate_disk(scene, plots);
  const double free = static_cast<double>(free_bytes(resolve_target(out)));
  if (disk.total() <= free) return;
  // The plots are estimated as the default scene's (kPlotsBytes): where they
  // make the difference, say how to do without them.
  const double unplotted = plots ? estimate_disk(scene, false).total() : disk.total();
  const std::string hint = unplotted < disk.total() && unplotted <= free
                               ? " (without the plots, --no-plots: about " + size_text(unplotted) + ")"
                               : "";
  throw InputError(
      "--out", to_text(out.string()),
      "a file system with room for the results: they need " + estimate_text(disk, free, "free") + hint);
}

}  // namespace shockgas::app
