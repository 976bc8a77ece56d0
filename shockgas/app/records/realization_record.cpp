#include "shockgas/app/records/realization_record.hpp"

#include <map>

#include "shockgas/app/files/byte_buffer.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::app {

namespace {

using particles::RunResult;

const char* const kStatesApart = "states_apart";  // a field of encode() only (not of the run)

void put_bodies(RecordFields& f, const std::string& prefix, const Bodies& b) {
  f.emplace_back(prefix + "/x", b.x);
  f.emplace_back(prefix + "/v", b.v);
  f.emplace_back(prefix + "/m", b.m);
}

// Field lookup by name with the malformed cases named.
// A text as numbers, one character code each (exact as doubles), and back.
std::vector<double> text_codes(const std::string& text) { return {text.begin(), text.end()}; }
std::string from_codes(const std::vector<double>& codes) {
  std::string text;
  for (double c : codes) text.push_back(static_cast<char>(c));
  return text;
}

class FieldReader {
 public:
  explicit FieldReader(const RecordFields& fields) {
    for (const auto& [name, data] : fields) by_name_[name] = &data;
  }
  bool has(const std::string& name) const { return by_name_.count(name) > 0; }
  const std::vector<double>& array(const std::string& name) const {
    const auto it = by_name_.find(name);
    if (it == by_name_.end()) throw RunError("realization record: no field " + name);
    return *it->second;
  }
  std::vector<double> numbers(const std::string& name, std::size_t count) const {
    const auto& a = array(name);
    if (a.size() != count)
      throw RunError("realization record: field " + name + " holds " + std::to_string(a.size()) +
                     " numbers, not " + std::to_string(count));
    return a;
  }
  Bodies bodies(const std::string& prefix) const {
    return {array(prefix + "/x"), array(prefix + "/v"), array(prefix + "/m")};
  }

 private:
  std::map<std::string, const std::vector<double>*> by_name_;
};

}  // namespace

void strip_states(RunResult& run) {
  run.final_state = {};
  run.snapshots = {};
  run.spacetime = {};
}

RecordFields to_fields(const RunResult& run) {
  RecordFields f;
  particles::TimeSeries series = run.series;
  series.for_each_column([&](const char* name, std::vector<double>& column) {
    f.emplace_back(std::string("series/") + name, std::move(column));
  });
  const auto& h = run.histogram;
  f.emplace_back("histogram/shape", std::vector<double>{h.zmax, static_cast<double>(h.bins)});
  f.emplace_back("histogram/t", h.t);
  f.emplace_back("histogram/density", h.density);
  f.emplace_back("stop",
                 std::vector<double>{static_cast<double>(run.stop.reason), run.stop.time, run.stop.position});
  f.emplace_back("collisions", std::vector<double>{static_cast<double>(run.collisions >> 32),
                                                   static_cast<double>(run.collisions & 0xFFFFFFFFu)});
  f.emplace_back("wall_seconds", std::vector<double>{run.wall_seconds});
  if (run.initial_temperature)
    f.emplace_back("initial_temperature", std::vector<double>{*run.initial_temperature});
  f.emplace_back("schedule/threads", std::vector<double>{static_cast<double>(run.schedule.threads)});
  f.emplace_back("schedule/order", text_codes(run.schedule.order));
  f.emplace_back("schedule/why_global", text_codes(run.schedule.why_global));
  if (run.final_state.size() > 0) put_bodies(f, "final", run.final_state);
  if (run.final_clusters) put_bodies(f, "clusters", *run.final_clusters);
  for (std::size_t k = 0; k < run.snapshots.size(); ++k) {
    const std::string prefix = "snapshots/" + std::to_string(k);
    f.emplace_back(prefix + "/t", std::vector<double>{run.snapshots[k].t});
    put_bodies(f, prefix, run.snapshots[k].bodies);
  }
  if (!run.spacetime.t.empty()) {
    f.emplace_back("spacetime/labels",
                   std::vector<double>(run.spacetime.labels.begin(), run.spacetime.labels.end()));
    f.emplace_back("spacetime/t", run.spacetime.t);
    f.emplace_back("spacetime/x", run.spacetime.x);
  }
  return f;
}

RunResult from_fields(const RecordFields& fields) {
  const FieldReader in(fields);
  RunResult run;
  run.series.for_each_column([&](const char* name, std::vector<double>& column) {
    column = in.array(std::string("series/") + name);
  });
  const auto shape = in.numbers("histogram/shape", 2);
  run.histogram.zmax = shape[0];
  run.histogram.bins = static_cast<std::size_t>(shape[1]);
  run.histogram.t = in.array("histogram/t");
  run.histogram.density = in.array("histogram/density");
  const auto stop = in.numbers("stop", 3);
  run.stop = {static_cast<particles::StopReason>(stop[0]), stop[1], stop[2]};
  const auto collisions = in.numbers("collisions", 2);
  run.collisions =
      (static_cast<std::uint64_t>(collisions[0]) << 32) | static_cast<std::uint64_t>(collisions[1]);
  run.wall_seconds = in.numbers("wall_seconds", 1)[0];
  if (in.has("initial_temperature")) run.initial_temperature = in.numbers("initial_temperature", 1)[0];
  run.schedule.threads = static_cast<std::size_t>(in.numbers("schedule/threads", 1)[0]);
  run.schedule.order = from_codes(in.array("schedule/order"));
  run.schedule.why_global = from_codes(in.array("schedule/why_global"));
  if (in.has("final/x")) run.final_state = in.bodies("final");
  if (in.has("clusters/x")) run.final_clusters = in.bodies("clusters");
  for (std::size_t k = 0; in.has("snapshots/" + std::to_string(k) + "/t"); ++k) {
    const std::string prefix = "snapshots/" + std::to_string(k);
    run.snapshots.push_back({in.numbers(prefix + "/t", 1)[0], in.bodies(prefix)});
  }
  if (in.has("spacetime/t")) {
    for (double label : in.array("spacetime/labels"))
      run.spacetime.labels.push_back(static_cast<std::size_t>(label));
    run.spacetime.t = in.array("spacetime/t");
    run.spacetime.x = in.array("spacetime/x");
  }
  return run;
}

// Bytes: the ensemble and index, then per field its name and numbers.
std::string encode(const RealizationRecord& record) {
  ByteWriter out;
  out.u64(record.ensemble);
  out.u64(record.index);
  for (const auto& [name, data] : to_fields(record.run)) out.text(name), out.numbers(data);
  if (record.states_apart) out.text(kStatesApart), out.numbers({1.0});
  return out.take();
}

RealizationRecord decode(const std::string& bytes) {
  ByteReader in(bytes, "realization record: message");
  RealizationRecord r;
  r.ensemble = in.u64();
  r.index = in.u64();
  RecordFields fields;
  while (!in.done()) {
    std::string name = in.text();
    std::vector<double> numbers = in.numbers();
    if (name == kStatesApart)
      r.states_apart = true;
    else
      fields.emplace_back(std::move(name), std::move(numbers));
  }
  r.run = from_fields(fields);
  return r;
}

}  // namespace shockgas::app
