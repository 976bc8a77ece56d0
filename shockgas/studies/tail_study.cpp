// `shockgas tail`: realizations reduced to folded tail histograms as they finish
// (tail_study.hpp), then the tail analysis per size and time (tail_files.cpp).
#include "shockgas/studies/tail_study.hpp"

#include <algorithm>
#include <cmath>
#include <ctime>
#include <filesystem>
#include <iostream>
#include <mutex>

#include "shockgas/core/cores.hpp"
#include "shockgas/core/error.hpp"
#include "shockgas/core/index_pool.hpp"
#include "shockgas/core/initial_condition.hpp"
#include "shockgas/core/interrupt.hpp"
#include "shockgas/core/sticky_hull.hpp"
#include "shockgas/particles/cluster_finder.hpp"
#include "shockgas/particles/simulate.hpp"
#include "shockgas/studies/tail_files.hpp"

namespace shockgas::studies {

namespace {

// CPU seconds of the calling thread.
double thread_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

double mean_velocity(const Bodies& b) {
  double p = 0, m = 0;
  for (std::size_t i = 0; i < b.size(); ++i) p += b.m[i] * b.v[i], m += b.m[i];
  return p / m;
}

// r = 0: the exact sticky gas at each time, advanced from the previous one.
TailRealization hull_realization(const InitialParams& ip, std::uint64_t k, const TailStudyOptions& o) {
  TailRealization out;
  double U = 0;
  StickyHull hull = [&] {
    const Bodies bodies = make_initial_bodies(ip, k);  // freed once the hull holds the clusters
    U = mean_velocity(bodies);
    return StickyHull::ring(bodies, static_cast<double>(ip.N), o.times.front());
  }();
  for (const double t : o.times) {
    hull.advance(t);
    compare::TailHistogram h(o.bin_width, o.z_max);
    double T = 0, M = 0;
    const double scale = std::cbrt(t);
    hull.for_each([&](const StickyCluster& c) {
      h.add((c.v - U) * scale, c.m);
      T += c.m * (c.v - U) * (c.v - U), M += c.m;
    });
    out.T.push_back(T / M);
    out.histograms.push_back(std::move(h));
  }
  out.collisions = ip.N - hull.size();  // merges
  return out;
}

// One state's clusters (default criteria of the threshold) into a histogram.
compare::TailHistogram state_histogram(const Bodies& b, double L, double U, double t,
                                       const TailStudyOptions& o, double* T) {
  compare::TailHistogram h(o.bin_width, o.z_max);
  const auto clusters =
      particles::find_clusters(b, L, particles::default_cluster_criteria(o.delta, L / double(b.size()), t));
  const double scale = std::cbrt(t);
  std::vector<double> z, m;
  double sum = 0, mass = 0;
  for (const particles::Cluster& c : clusters) {
    z.clear(), m.clear();
    for (std::size_t j = c.first; j < c.first + c.count; ++j) {
      const std::size_t i = j % b.size();
      z.push_back((b.v[i] - U) * scale), m.push_back(b.m[i]);
      sum += b.m[i] * (b.v[i] - U) * (b.v[i] - U), mass += b.m[i];
    }
    h.add_members(z, m);
  }
  *T = sum / mass;
  return h;
}

// r > 0: the event engine, its states at the times.
TailRealization engine_realization(const InitialParams& ip, std::uint64_t k, const TailStudyOptions& o) {
  const Bodies bodies = make_initial_bodies(ip, k);
  const double L = static_cast<double>(ip.N), U = mean_velocity(bodies);
  particles::ParticleParams p;
  p.r = o.r, p.delta = o.delta, p.t_end = o.times.back(), p.samples = 2, p.clusters = false, p.threads = 1;
  p.snapshots.assign(o.times.begin(), o.times.end() - 1);
  const particles::RunResult run = particles::simulate(bodies, L, p);
  if (run.stop.reason != particles::StopReason::completed)
    throw RunError("tail: realization " + std::to_string(k) + " stopped at t = " + to_text(run.stop.time) +
                   " (" + particles::to_string(run.stop.reason) + ")");
  TailRealization out;
  for (std::size_t j = 0; j < o.times.size(); ++j) {
    const Bodies& state = j + 1 < o.times.size() ? run.snapshots[j].bodies : run.final_state;
    double T = 0;
    out.histograms.push_back(state_histogram(state, L, U, o.times[j], o, &T));
    out.T.push_back(T);
  }
  out.collisions = run.collisions;
  return out;
}

}  // namespace

std::string tail_sizes_allowed() {
  return "distinct whole numbers from " + std::to_string(kTailMinN) + " to " + fmt(kTailMaxN, 2);
}

void validate_tail_study(const TailStudyOptions& o) {
  require(!o.out_dir.empty(), "tail.out", o.out_dir, "a directory name");
  require(!o.sizes.empty(), "tail.N", o.sizes.size(), "at least one size");
  for (std::size_t i = 0; i < o.sizes.size(); ++i) {
    const std::size_t N = o.sizes[i];
    const bool repeated = std::find(o.sizes.begin(), o.sizes.begin() + static_cast<std::ptrdiff_t>(i), N) !=
                          o.sizes.begin() + static_cast<std::ptrdiff_t>(i);
    require(N >= kTailMinN && static_cast<double>(N) <= kTailMaxN && !repeated, "tail.N", N,
            tail_sizes_allowed());
  }
  require(o.realizations >= 2, "tail.realizations", o.realizations,
          ">= 2 (the errors are a jackknife over them)");
  require(!o.times.empty(), "tail.times", o.times.size(), "at least one time");
  for (std::size_t j = 0; j < o.times.size(); ++j)
    require(o.times[j] > 0 && (j == 0 || o.times[j] > o.times[j - 1]), "tail.times", o.times[j],
            "increasing times > 0");
  require_in_range("tail.r", o.r, 0.0, 1.0);
  require(o.r == 0 || o.delta > 0, "tail.delta", o.delta, "> 0 for r > 0");
  require(o.bin_width > 0 && o.z_max > o.bin_width, "tail.bin_width", o.bin_width, "0 < bin_width < z_max");
  require(o.min_clusters >= 1, "tail.min_clusters", o.min_clusters,
          ">= 1 (clusters a bin must hold to count)");
}

namespace {

// Realizations 0..R-1 of size N on `threads` threads, reduced as they finish.
TailEnsemble run_size(std::size_t N, const TailStudyOptions& o) {
  InitialParams ip;
  ip.N = N;
  ip.seed = o.seed;
  TailEnsemble ensemble(o.realizations, kTailJackknifeGroups);
  std::size_t done = 0;
  std::mutex mutex;
  run_indices(o.realizations, o.threads == 0 ? usable_cores() : o.threads, [&](std::size_t k) {
    throw_if_aborted();  // between realizations: nothing is half written
    const double start = thread_cpu_seconds();
    TailRealization run = o.r == 0 ? hull_realization(ip, k, o) : engine_realization(ip, k, o);
    run.cpu_seconds = thread_cpu_seconds() - start;
    std::lock_guard lock(mutex);
    ensemble.add(k, std::move(run));
    if (o.progress)
      std::cerr << "tail: N = " << N << ": " << ++done << "/" << o.realizations << " realizations\n";
  });
  return ensemble;
}

}  // namespace

std::string run_tail_study(const TailStudyOptions& o) {
  validate_tail_study(o);
  std::error_code ec;
  std::filesystem::create_directories(o.out_dir, ec);
  if (ec || !std::filesystem::is_directory(o.out_dir))
    throw InputError("tail.out", to_text(o.out_dir), "a directory that can be created");
  TailFiles files(o);
  for (const std::size_t N : o.sizes) {
    files.add(N, run_size(N, o));
    if (o.size_written) o.size_written();
  }
  return o.out_dir;
}

}  // namespace shockgas::studies
