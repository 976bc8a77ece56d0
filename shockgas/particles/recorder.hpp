#pragma once
// The observer of a particle run (private to particles/): it owns the schedule
// of stop times (samples, snapshots, space-time frames) and turns the state at
// each stop into the records of RunResult. Used by the event engine and by the
// exact hull model alike, so both report the same observables.
#include <cstdint>
#include <limits>
#include <vector>

#include "shockgas/core/bodies.hpp"
#include "shockgas/particles/chain_observables.hpp"
#include "shockgas/particles/chain_view.hpp"
#include "shockgas/particles/cluster_finder.hpp"
#include "shockgas/particles/params.hpp"
#include "shockgas/particles/ring_wrap.hpp"
#include "shockgas/particles/run_result.hpp"
#include "shockgas/particles/run_state.hpp"
#include "shockgas/particles/state_sink.hpp"
#include "shockgas/particles/stretch_observables.hpp"

namespace shockgas::particles::detail {

// Cumulative collision counters at a stop.
struct Counters {
  std::uint64_t all = 0, inelastic = 0, elastic = 0, merges = 0;
  double dissipated = 0;  // [mass length^2/time^2]
};

// Sample times: `samples` log-spaced times from 1 to t_end (from t_end / 1000 if
// t_end <= 1); just t_end if samples = 1. The last is t_end exactly.
std::vector<double> sample_times(double t_end, std::size_t samples);

class Recorder {
 public:
  static constexpr double done = std::numeric_limits<double>::infinity();

  // n: original particles; L: ring length or line extent (for the cluster
  // criteria); mean_particle_mass: their M / N (MultiParticleRule). With a sink,
  // the snapshots and the final state go to it, sorted (sorted_state.hpp),
  // instead of into RunResult.
  Recorder(const ParticleParams& p, std::size_t n, double L, bool ring, double mean_particle_mass,
           const StateSink* sink = nullptr);

  // The next time the run must reach and observe; `done` after the last.
  double next_stop() const;
  // Observes every record due at t = next_stop(); each observable only if asked.
  void observe(double t, const ChainView& s, const Counters& c);
  // The sample times from the next stop on that a model may measure in parts
  // (stretch_observables.hpp) and hand over by observe_sample: those before any
  // other record (snapshot, frame), without duplicates; none when a histogram is
  // asked for (it bins about the mean of the whole state), nor when the count
  // needs the clusters' masses (MultiParticleRule::streams).
  std::vector<double> samples_in_parts() const;
  // What those parts measure at time t.
  SampleSpec sample_spec(double t) const { return {p_.clusters, criteria(t), series_, L_, ring_}; }
  // Records the samples due at t from their combined parts.
  void observe_sample(double t, const SampleMoments& moments, std::size_t clusters, const Counters& c);
  // Moves the records out, with the final state at stop.time and how the run ended.
  RunResult finish(const ChainView& final_state, const RunStop& stop, const Counters& c);
  // The records so far and which stops are passed (run_state.hpp;
  // recorder_state.cpp), and back into a recorder made with the same parameters.
  void save(RunStateWriter& out) const;
  void restore(RunStateReader& in);

 private:
  void sample(double t, const ChainView& s, const Counters& c, std::size_t copies);
  // The row of every sample due at t (copies of them), histogram row if any.
  struct Row {
    double T = 0, mean_v = 0, bodies = 0, clusters = 0;
  };
  void record(double t, const Row& row, const Counters& c, std::size_t copies,
              const std::vector<double>& density);
  // The cluster criteria at time t: gas_cluster_criteria(r, delta, L / n, t).
  ClusterCriteria criteria(double t) const;
  std::size_t count_clusters(double t, const ChainView& s, ClusterCounter* counter) const;
  void snapshot(double t, const ChainView& s, std::size_t copies);
  void frame(double t, const ChainView& s);
  double wrap(double x) const;
  Bodies final_clusters(const ChainView& s, double t) const;

  const ParticleParams& p_;
  std::size_t n_;
  double L_;
  bool ring_;
  const StateSink* sink_;
  double spacing_;             // L / n [length]
  MultiParticleRule counted_;  // the final clusters: those of two or more particles
  MultiParticleRule series_;   // the sample times' count: particles.min_cluster_particles
  std::vector<double> samples_, snapshots_, frames_;
  std::size_t next_sample_ = 0, next_snapshot_ = 0, next_frame_ = 0;
  RunResult out_;
};

}  // namespace shockgas::particles::detail
