#include "recorder.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numeric>

namespace shockgas::particles::detail {

namespace {

double wrap_into(double x, double L) {
  double w = x - L * std::floor(x / L);
  return w >= L || w < 0 ? 0.0 : w;
}

// Mass-weighted mean velocity and temperature <v^2> - <v>^2 (two passes: no
// cancellation).
std::pair<double, double> mean_and_temperature(const ChainState& s) {
  double mass = 0, momentum = 0;
  for (std::size_t b = 0; b < s.v.size(); ++b) mass += s.m[b], momentum += s.m[b] * s.v[b];
  const double mean = momentum / mass;
  double T = 0;
  for (std::size_t b = 0; b < s.v.size(); ++b) T += s.m[b] * (s.v[b] - mean) * (s.v[b] - mean);
  return {mean, T / mass};
}

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

Bodies sorted_bodies(const ChainState& s, double L, bool ring) {
  const std::size_t n = s.x.size();
  std::vector<double> x = s.x;
  std::size_t start = 0;
  if (ring) {
    for (double& xi : x) xi = wrap_into(xi, L);
    for (std::size_t b = 1; b < n; ++b)
      if (x[b] < x[b - 1]) {
        start = b;
        break;
      }
  }
  std::vector<std::size_t> order(n);
  for (std::size_t k = 0; k < n; ++k) order[k] = (start + k) % n;
  // Rounding at the wrap can leave equal neighbours misordered: sort to be sure.
  auto by_x = [&](std::size_t a, std::size_t b) { return x[a] < x[b]; };
  if (!std::is_sorted(order.begin(), order.end(), by_x)) std::stable_sort(order.begin(), order.end(), by_x);
  Bodies out;
  out.reserve(n);
  for (std::size_t k : order) out.push_back(x[k], s.v[k], s.m[k]);
  return out;
}

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

Recorder::Recorder(const ParticleParams& p, std::size_t n, double L, bool ring)
    : p_(p), n_(n), L_(L), ring_(ring) {
  samples_ = sample_times(p.t_end, p.samples);
  snapshots_ = sorted_copy(p.snapshots);
  if (p.spacetime) frames_ = frame_times(p.t_end, p.spacetime_frames);
  criteria_ = p.r == 0 && (p.delta == 0 || p.subthreshold == Subthreshold::sticky)
                  ? merged_bodies_criteria()
                  : default_cluster_criteria(p.delta, L / static_cast<double>(n));
  out_.histogram.zmax = p.histogram_zmax;
  out_.histogram.bins = p.histogram_bins;
  out_.spacetime.n = p.spacetime ? n : 0;
}

double Recorder::next_stop() const {
  double t = done;
  if (next_sample_ < samples_.size()) t = std::min(t, samples_[next_sample_]);
  if (next_snapshot_ < snapshots_.size()) t = std::min(t, snapshots_[next_snapshot_]);
  if (next_frame_ < frames_.size()) t = std::min(t, frames_[next_frame_]);
  return t;
}

void Recorder::observe(double t, const ChainState& s, const Counters& c) {
  const bool want_sample = next_sample_ < samples_.size() && samples_[next_sample_] <= t;
  const bool want_snapshot = next_snapshot_ < snapshots_.size() && snapshots_[next_snapshot_] <= t;
  Bodies sorted;
  if ((want_sample && p_.clusters) || want_snapshot) sorted = sorted_bodies(s, L_, ring_);
  for (; next_sample_ < samples_.size() && samples_[next_sample_] <= t; ++next_sample_)
    sample(t, s, sorted, c);
  for (; next_snapshot_ < snapshots_.size() && snapshots_[next_snapshot_] <= t; ++next_snapshot_)
    out_.snapshots.push_back({t, sorted});
  for (; next_frame_ < frames_.size() && frames_[next_frame_] <= t; ++next_frame_) frame(t, s);
}

void Recorder::sample(double t, const ChainState& s, const Bodies& sorted, const Counters& c) {
  TimeSeries& ts = out_.series;
  const auto [mean, T] = mean_and_temperature(s);
  ts.t.push_back(t);
  ts.T.push_back(T);
  ts.mean_v.push_back(mean);
  ts.n_bodies.push_back(static_cast<double>(s.x.size()));
  if (p_.clusters)
    ts.n_clusters.push_back(static_cast<double>(find_clusters(sorted, ring_ ? L_ : 0.0, criteria_).size()));
  ts.collisions.push_back(static_cast<double>(c.all));
  ts.inelastic.push_back(static_cast<double>(c.inelastic));
  ts.elastic.push_back(static_cast<double>(c.elastic));
  ts.merges.push_back(static_cast<double>(c.merges));
  ts.dissipated.push_back(c.dissipated);
  if (p_.histogram_bins > 0) histogram(t, s);
}

void Recorder::histogram(double t, const ChainState& s) {
  ScaledHistogram& h = out_.histogram;
  const std::size_t bins = h.bins;
  const double dz = 2 * h.zmax / static_cast<double>(bins);
  const auto [mean, T] = mean_and_temperature(s);
  const double mass = std::accumulate(s.m.begin(), s.m.end(), 0.0);
  const double scale = std::cbrt(t);
  h.t.push_back(t);
  h.density.resize(h.density.size() + bins, 0.0);
  double* row = h.density.data() + h.density.size() - bins;
  for (std::size_t b = 0; b < s.v.size(); ++b) {
    const double bin = std::floor(((s.v[b] - mean) * scale + h.zmax) / dz);
    if (bin >= 0 && bin < static_cast<double>(bins))
      row[static_cast<std::size_t>(bin)] += s.m[b] / (mass * dz);
  }
}

void Recorder::frame(double t, const ChainState& s) {
  SpaceTime& st = out_.spacetime;
  st.t.push_back(t);
  const std::size_t base = st.x.size();
  st.x.resize(base + n_);
  const std::size_t bodies = s.x.size();
  for (std::size_t b = 0; b < bodies; ++b) {
    const std::size_t end = b + 1 < bodies ? s.first[b + 1] : n_;
    const double x = ring_ ? wrap(s.x[b]) : s.x[b];
    for (std::size_t k = s.first[b]; k < end; ++k) st.x[base + k] = x;
  }
  // Ring: the particles before the first body's belong to the last body.
  for (std::size_t k = 0; k < s.first.front(); ++k) st.x[base + k] = wrap(s.x.back());
}

double Recorder::wrap(double x) const { return ring_ ? wrap_into(x, L_) : x; }

RunResult Recorder::finish(const ChainState& final_state, const RunStop& stop, const Counters& c) {
  out_.final_state = sorted_bodies(final_state, L_, ring_);
  out_.stop = stop;
  out_.stop.position =
      stop.reason == StopReason::collapse || stop.reason == StopReason::stall ? wrap(stop.position) : 0.0;
  out_.collisions = c.all;
  return std::move(out_);
}

}  // namespace shockgas::particles::detail
