// Ensembles of realizations: run on worker threads, combined in index order so
// that the result does not depend on the number of threads.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <mutex>

#include "shockgas/core/cores.hpp"
#include "shockgas/core/index_pool.hpp"
#include "shockgas/core/interrupt.hpp"
#include "shockgas/particles/simulate.hpp"

namespace shockgas::particles {

namespace {

// Mean and standard error of column `col` over runs, per sample index.
SeriesStats stats(const std::vector<RunResult>& runs, std::size_t samples,
                  std::vector<double> TimeSeries::*col) {
  SeriesStats s{std::vector<double>(samples, 0.0), std::vector<double>(samples, 0.0)};
  for (std::size_t k = 0; k < samples; ++k) {
    double sum = 0, n = 0;
    for (const RunResult& r : runs)
      if (k < (r.series.*col).size()) sum += (r.series.*col)[k], n += 1;
    if (n == 0) continue;
    const double mean = sum / n;
    double ss = 0;
    for (const RunResult& r : runs)
      if (k < (r.series.*col).size()) ss += ((r.series.*col)[k] - mean) * ((r.series.*col)[k] - mean);
    s.mean[k] = mean;
    s.stderr_[k] = n > 1 ? std::sqrt(ss / (n - 1) / n) : 0.0;
  }
  return s;
}

std::vector<double> mean_histogram(const std::vector<RunResult>& runs) {
  std::vector<double> h;
  std::vector<double> n;
  for (const RunResult& r : runs) {
    const std::vector<double>& d = r.histogram.density;
    if (d.size() > h.size()) h.resize(d.size(), 0.0), n.resize(d.size(), 0.0);
    for (std::size_t i = 0; i < d.size(); ++i) h[i] += d[i], n[i] += 1;
  }
  for (std::size_t i = 0; i < h.size(); ++i) h[i] /= n[i];
  return h;
}

// Thread-safe progress: the mean of the workers' fractions, the sum of their events.
class SharedProgress {
 public:
  SharedProgress(const ProgressCallback& cb, std::size_t runs)
      : cb_(cb), fraction_(runs, 0.0), events_(runs, 0) {}
  ProgressCallback for_run(std::size_t k) {
    if (!cb_) return {};
    return [this, k](double f, double t, std::uint64_t events) { report(k, f, t, events); };
  }
  void report(std::size_t k, double f, double t, std::uint64_t events) {
    std::lock_guard lock(mutex_);
    fraction_[k] = f;
    events_[k] = events;
    double sum = 0;
    std::uint64_t all = 0;
    for (std::size_t i = 0; i < fraction_.size(); ++i) sum += fraction_[i], all += events_[i];
    cb_(sum / static_cast<double>(fraction_.size()), t, all);
  }

 private:
  const ProgressCallback& cb_;
  std::mutex mutex_;
  std::vector<double> fraction_;
  std::vector<std::uint64_t> events_;
};

// What a realization that never ran because of a checkpoint request reports.
RunResult not_started() {
  RunResult r;
  r.stop = {StopReason::interrupted, 0.0, 0.0};
  return r;
}

std::vector<RunResult> run_all(const InitialCondition& ic, const ParticleParams& p,
                               SharedProgress& progress) {
  const std::size_t R = p.realizations;
  const ThreadSplit split = split_threads(p.threads > 0 ? p.threads : usable_cores(), R);
  ParticleParams each = p;
  each.threads = split.per_run;
  std::vector<RunResult> runs(R);
  run_indices(R, split.runs, [&](std::size_t k) {
    if (interrupt_requested() != InterruptMode::none) {
      throw_if_aborted();
      runs[k] = not_started();
      return;
    }
    runs[k] = run_realization(ic, k, each, progress.for_run(k));
    if (ProgressCallback cb = progress.for_run(k)) cb(1.0, p.t_end, runs[k].collisions);
  });
  return runs;
}

}  // namespace

RunResult run_realization(const InitialCondition& ic, std::uint64_t k, const ParticleParams& p,
                          const ProgressCallback& progress, const RunCheckpoints& checkpoints) {
  if (k == 0) return simulate(ic, k, p, progress, nullptr, checkpoints);
  const StateSink discard;
  RunResult r = simulate(ic, k, p, progress, &discard, checkpoints);
  r.spacetime = {};
  return r;
}

ThreadSplit split_threads(std::size_t threads, std::size_t realizations) {
  ThreadSplit s;
  s.runs = std::max<std::size_t>(1, std::min(threads, realizations));
  s.per_run = std::max<std::size_t>(1, threads / s.runs);
  return s;
}

EnsembleResult run_ensemble(const InitialParams& ip, const ParticleParams& p,
                            const ProgressCallback& progress) {
  return run_ensemble(InitialCondition(ip, InitialCondition::Keep::stream), p, progress);
}

EnsembleResult run_ensemble(const InitialCondition& ic, const ParticleParams& p,
                            const ProgressCallback& progress) {
  validate(p);
  const auto start = std::chrono::steady_clock::now();
  SharedProgress shared(progress, p.realizations);
  EnsembleResult e = reduce_ensemble(run_all(ic, p, shared));
  e.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return e;
}

EnsembleResult reduce_ensemble(std::vector<RunResult> runs) {
  EnsembleResult e;
  std::size_t samples = 0;
  for (const RunResult& r : runs) samples = std::max(samples, r.series.size());
  for (const RunResult& r : runs)
    if (r.series.size() == samples) e.t = r.series.t;
  e.count.assign(samples, 0.0);
  for (const RunResult& r : runs)
    for (std::size_t k = 0; k < r.series.size(); ++k) e.count[k] += 1;
  e.T = stats(runs, samples, &TimeSeries::T);
  e.mean_v = stats(runs, samples, &TimeSeries::mean_v);
  e.n_bodies = stats(runs, samples, &TimeSeries::n_bodies);
  e.n_clusters = stats(runs, samples, &TimeSeries::n_clusters);
  e.collisions = stats(runs, samples, &TimeSeries::collisions);
  e.inelastic = stats(runs, samples, &TimeSeries::inelastic);
  e.elastic = stats(runs, samples, &TimeSeries::elastic);
  e.merges = stats(runs, samples, &TimeSeries::merges);
  e.dissipated = stats(runs, samples, &TimeSeries::dissipated);
  e.histogram = mean_histogram(runs);
  for (const RunResult& r : runs) {
    e.T_by_realization.push_back(r.series.T);
    e.histogram_by_realization.push_back(r.histogram.density);
    e.final_clusters.push_back(r.final_clusters);
    e.stops.push_back(r.stop);
    e.collisions_per_realization.push_back(r.collisions);
    e.total_collisions += r.collisions;
  }
  e.first = std::move(runs.front());
  return e;
}

}  // namespace shockgas::particles
