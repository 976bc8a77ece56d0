#include "shockgas/particles/recorder.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "shockgas/particles/sorted_state.hpp"

namespace shockgas::particles::detail {

namespace {

std::vector<double> sorted_copy(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v;
}

std::vector<double> frame_times(double t_end, std::size_t frames) {
  std::vector<double> t(frames);
  for (std::size_t k = 0; k < frames; ++k) t[k] = t_end * static_cast<double>(k) / (frames - 1);
  t.back() = t_end;
  return t;
}

}  // namespace

std::vector<double> sample_times(double t_end, std::size_t samples) {
  if (samples == 1) return {t_end};
  const double t0 = t_end > 1 ? 1.0 : t_end / 1000;
  std::vector<double> t(samples);
  for (std::size_t k = 0; k < samples; ++k)
    t[k] = t0 * std::pow(t_end / t0, static_cast<double>(k) / (samples - 1));
  t.front() = t0;
  t.back() = t_end;
  return t;
}

Recorder::Recorder(const ParticleParams& p, std::size_t n, double L, bool ring, double mean_particle_mass,
                   const StateSink* sink)
    : p_(p),
      n_(n),
      L_(L),
      ring_(ring),
      sink_(sink),
      spacing_(L / static_cast<double>(n)),
      counted_(mean_particle_mass),
      series_(mean_particle_mass, p.min_cluster_particles) {
  samples_ = sample_times(p.t_end, p.samples);
  snapshots_ = sorted_copy(p.snapshots);
  if (p.spacetime) frames_ = frame_times(p.t_end, p.spacetime_frames);
  out_.histogram.zmax = p.histogram_zmax;
  out_.histogram.bins = p.histogram_bins;
  if (p.spacetime) out_.spacetime.labels = spacetime_labels(n, p.spacetime_particles);
}

ClusterCriteria Recorder::criteria(double t) const {
  return gas_cluster_criteria(p_.r, p_.delta, spacing_, t);
}

double Recorder::next_stop() const {
  double t = done;
  if (next_sample_ < samples_.size()) t = std::min(t, samples_[next_sample_]);
  if (next_snapshot_ < snapshots_.size()) t = std::min(t, snapshots_[next_snapshot_]);
  if (next_frame_ < frames_.size()) t = std::min(t, frames_[next_frame_]);
  return t;
}

void Recorder::observe(double t, const ChainView& s, const Counters& c) {
  std::size_t samples = 0, snapshots = 0;
  for (; next_sample_ < samples_.size() && samples_[next_sample_] <= t; ++next_sample_) ++samples;
  for (; next_snapshot_ < snapshots_.size() && snapshots_[next_snapshot_] <= t; ++next_snapshot_) ++snapshots;
  if (samples > 0) sample(t, s, c, samples);
  if (snapshots > 0) snapshot(t, s, snapshots);
  for (; next_frame_ < frames_.size() && frames_[next_frame_] <= t; ++next_frame_) frame(t, s);
}

// Every sample due at t records the same values: they are measured once.
void Recorder::sample(double t, const ChainView& s, const Counters& c, std::size_t copies) {
  std::optional<ClusterCounter> counter;
  if (p_.clusters && series_.streams()) counter.emplace(L_, ring_, criteria(t), series_);
  const ChainMoments moments = chain_moments(s, counter ? &*counter : nullptr);
  const HistogramSpec spec{p_.histogram_bins, p_.histogram_zmax, std::cbrt(t)};
  std::vector<double> density;
  const double T = chain_temperature(s, moments, spec, spec.bins > 0 ? &density : nullptr);
  const double clusters =
      p_.clusters ? static_cast<double>(count_clusters(t, s, counter ? &*counter : nullptr)) : 0.0;
  record(t, {T, moments.mean(), static_cast<double>(s.size()), clusters}, c, copies, density);
}

std::vector<double> Recorder::samples_in_parts() const {
  std::vector<double> t;
  if (p_.histogram_bins > 0 || (p_.clusters && !series_.streams())) return t;
  double other = done;
  if (next_snapshot_ < snapshots_.size()) other = snapshots_[next_snapshot_];
  if (next_frame_ < frames_.size()) other = std::min(other, frames_[next_frame_]);
  for (std::size_t k = next_sample_; k < samples_.size() && samples_[k] < other; ++k)
    if (t.empty() || samples_[k] > t.back()) t.push_back(samples_[k]);
  return t;
}

void Recorder::observe_sample(double t, const SampleMoments& moments, std::size_t clusters,
                              const Counters& c) {
  std::size_t copies = 0;
  for (; next_sample_ < samples_.size() && samples_[next_sample_] <= t; ++next_sample_) ++copies;
  const Row row{moments.T, moments.momentum / moments.mass, static_cast<double>(moments.bodies),
                static_cast<double>(clusters)};
  record(t, row, c, copies, {});
}

void Recorder::record(double t, const Row& row, const Counters& c, std::size_t copies,
                      const std::vector<double>& density) {
  TimeSeries& ts = out_.series;
  for (std::size_t k = 0; k < copies; ++k) {
    ts.t.push_back(t);
    ts.T.push_back(row.T);
    ts.mean_v.push_back(row.mean_v);
    ts.n_bodies.push_back(row.bodies);
    if (p_.clusters) ts.n_clusters.push_back(row.clusters);
    ts.collisions.push_back(static_cast<double>(c.all));
    ts.inelastic.push_back(static_cast<double>(c.inelastic));
    ts.elastic.push_back(static_cast<double>(c.elastic));
    ts.merges.push_back(static_cast<double>(c.merges));
    ts.dissipated.push_back(c.dissipated);
    if (p_.histogram_bins == 0) continue;
    out_.histogram.t.push_back(t);
    out_.histogram.density.insert(out_.histogram.density.end(), density.begin(), density.end());
  }
}

// The `copies` snapshots due at t (the last ones passed), into RunResult or the sink.
void Recorder::snapshot(double t, const ChainView& s, std::size_t copies) {
  if (!sink_) {
    const Bodies sorted = sorted_bodies(s, L_, ring_);
    for (std::size_t k = 0; k < copies; ++k) out_.snapshots.push_back({t, sorted});
    return;
  }
  if (!sink_->snapshot) return;
  const SortedState sorted(s, L_, ring_);
  for (std::size_t k = next_snapshot_ - copies; k < next_snapshot_; ++k) sink_->snapshot(k, t, sorted);
}

// The streamed count, or (no counter: the rule needs the clusters' masses;
// rounding left the chain out of order) the count of the state read in order
// (SortedState), as find_clusters would count it.
std::size_t Recorder::count_clusters(double t, const ChainView& s, ClusterCounter* counter) const {
  if (counter)
    if (const std::optional<std::size_t> n = counter->count()) return *n;
  std::size_t clusters = 0;
  visit_clusters(SortedState(s, L_, ring_), ring_ ? L_ : 0.0, criteria(t),
                 [&](const Cluster& c) { clusters += series_.counts(c); });
  return clusters;
}

// Each recorded particle at its body's position: body b holds the labels
// first[b] .. first[b+1]-1, the last body the rest up to n and (ring) those
// before first[0]; column(l) is the column of the first recorded label >= l.
void Recorder::frame(double t, const ChainView& s) {
  SpaceTime& st = out_.spacetime;
  const std::vector<std::size_t>& labels = st.labels;
  st.t.push_back(t);
  const std::size_t base = st.x.size();
  st.x.resize(base + labels.size());
  double* const row = st.x.data() + base;
  auto column = [&](std::size_t l) {
    return row + (std::lower_bound(labels.begin(), labels.end(), l) - labels.begin());
  };
  std::size_t first = 0, pending = 0;
  bool started = false;
  double x = 0;
  s.visit(
      [&](const ChainChunk& c) {
        for (std::size_t k = 0; k < c.size; ++k) {
          if (started)
            std::fill(column(pending), column(c.first[k]), x);  // the previous body's particles
          else
            first = c.first[k], started = true;
          pending = c.first[k];
          x = wrap(c.x[k]);
        }
      },
      Fields::all);
  std::fill(column(pending), row + labels.size(), x);
  std::fill(row, column(first), x);
}

double Recorder::wrap(double x) const { return ring_ ? wrap_into(x, L_) : x; }

// The clusters of at least two particles at t (RunResult::final_clusters), by
// the criteria the time series counts with (criteria(t)) and the rule of two
// or more particles (counted_: MultiParticleRule), whatever
// particles.min_cluster_particles: the statistics see every cluster. Counted
// first, then kept: no vector grows past what it holds. They come in order of
// x but for the cluster across a ring's wrap, which comes last and may belong
// first (and, should rounding put a centre of mass out of order, are sorted).
Bodies Recorder::final_clusters(const ChainView& s, double t) const {
  const ClusterCriteria at_t = criteria(t);
  const SortedState sorted(s, L_, ring_);
  const double L = ring_ ? L_ : 0.0;
  std::size_t count = 0;
  visit_clusters(sorted, L, at_t, [&](const Cluster& k) { count += counted_.counts(k); });
  Bodies found;
  found.reserve(count);
  visit_clusters(sorted, L, at_t, [&](const Cluster& k) {
    if (counted_.counts(k)) found.push_back(k.x, k.v, k.m);
  });
  if (found.size() >= 2 && found.x.back() < found.x.front())
    for (auto* column : {&found.x, &found.v, &found.m})
      std::rotate(column->begin(), column->end() - 1, column->end());
  if (std::is_sorted(found.x.begin(), found.x.end())) return found;
  std::vector<std::size_t> order(found.size());  // rounding: a centre of mass out of order
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return found.x[a] < found.x[b]; });
  Bodies in_order;
  in_order.reserve(order.size());
  for (std::size_t k : order) in_order.push_back(found.x[k], found.v[k], found.m[k]);
  return in_order;
}

RunResult Recorder::finish(const ChainView& final_state, const RunStop& stop, const Counters& c) {
  if (records_final_clusters(p_, n_)) out_.final_clusters = final_clusters(final_state, stop.time);
  if (!sink_)
    out_.final_state = sorted_bodies(final_state, L_, ring_);
  else if (sink_->final_state)
    sink_->final_state(stop.time, SortedState(final_state, L_, ring_));
  out_.stop = stop;
  out_.stop.position =
      stop.reason == StopReason::collapse || stop.reason == StopReason::stall ? wrap(stop.position) : 0.0;
  out_.collisions = c.all;
  return std::move(out_);
}

}  // namespace shockgas::particles::detail
