// The recorder's part of a saved run (run_state.hpp): the records taken so far
// (time series, histogram rows, snapshots, space-time frames) and the index of
// the next stop of each kind.
#include "shockgas/particles/recorder.hpp"
#include "shockgas/particles/state_io.hpp"

namespace shockgas::particles::detail {

namespace {

constexpr std::uint64_t kRecorderTag = 0x3173647263655200ull;  // "\0Recrds1"

void put_bodies(RunStateWriter& out, const Bodies& b) {
  put_vector(out, b.x), put_vector(out, b.v), put_vector(out, b.m);
}
void get_bodies(RunStateReader& in, Bodies& b) {
  get_vector(in, b.x, "a snapshot"), get_vector(in, b.v, "a snapshot"), get_vector(in, b.m, "a snapshot");
}

}  // namespace

void Recorder::save(RunStateWriter& out) const {
  put(out, kRecorderTag);
  put<std::uint64_t>(out, next_sample_), put<std::uint64_t>(out, next_snapshot_);
  put<std::uint64_t>(out, next_frame_);
  TimeSeries series = out_.series;  // for_each_column visits mutable columns; the copy is small
  series.for_each_column([&](const char*, const std::vector<double>& column) { put_vector(out, column); });
  put_vector(out, out_.histogram.t), put_vector(out, out_.histogram.density);
  put<std::uint64_t>(out, out_.snapshots.size());
  for (const Snapshot& s : out_.snapshots) put(out, s.t), put_bodies(out, s.bodies);
  put_vector(out, out_.spacetime.t), put_vector(out, out_.spacetime.x);
}

void Recorder::restore(RunStateReader& in) {
  expect(in, kRecorderTag, "records tag");
  next_sample_ = get<std::uint64_t>(in), next_snapshot_ = get<std::uint64_t>(in);
  next_frame_ = get<std::uint64_t>(in);
  if (next_sample_ > samples_.size() || next_snapshot_ > snapshots_.size() || next_frame_ > frames_.size())
    throw RunError("a saved run state: its records do not fit the run it is resumed in (other stop times)");
  out_.series.for_each_column(
      [&](const char*, std::vector<double>& column) { get_vector(in, column, "a series"); });
  get_vector(in, out_.histogram.t, "the histogram"), get_vector(in, out_.histogram.density, "the histogram");
  out_.snapshots.resize(get_count(in, 4 * sizeof(double), "the snapshots"));
  for (Snapshot& s : out_.snapshots) s.t = get<double>(in), get_bodies(in, s.bodies);
  get_vector(in, out_.spacetime.t, "the space-time record"),
      get_vector(in, out_.spacetime.x, "the space-time record");
  if (out_.spacetime.x.size() != out_.spacetime.t.size() * out_.spacetime.labels.size())
    throw RunError(
        "a saved run state: its space-time record does not fit the run it is resumed in (other "
        "particles.spacetime_particles)");
}

}  // namespace shockgas::particles::detail
