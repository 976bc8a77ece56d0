// The datasets, attributes and summary keys of a shard (shard_file.hpp),
// declared once: a shard holds the records of its slice of a run
// (realization_record.hpp), one dataset per field, and says which slice it is.
#include <nlohmann/json.hpp>

#include "shockgas/app/output/layout_declarations.hpp"

namespace shockgas::app::layout {

namespace {

template <class F>
Emit from_shard(F f) {
  return [f](const RunResults& r, Emitter& out) {
    if (r.shard) f(*r.shard, out);
  };
}

std::vector<std::string> segments(const std::string& name) {
  std::vector<std::string> s;
  for (std::size_t at = 0, next; at <= name.size(); at = next + 1) {
    next = std::min(name.find('/', at), name.size());
    s.push_back(name.substr(at, next - at));
  }
  return s;
}

// The record fields whose names have `depth` segments, each at {e}/{k}/<its segments>
// (`skip` leading literal segments of the declared path left out).
Emit fields_of_depth(std::size_t depth, std::size_t skip) {
  return from_shard([depth, skip](const ShardResults& s, Emitter& out) {
    for (const RealizationRecord& r : s.records)
      for (const auto& [name, data] : to_fields(r.run)) {
        const auto parts = segments(name);
        if (parts.size() != depth || (skip > 0 && parts[0] != "snapshots")) continue;
        std::vector<std::string> at = {std::to_string(r.ensemble), std::to_string(r.index)};
        at.insert(at.end(), parts.begin() + static_cast<std::ptrdiff_t>(skip), parts.end());
        out.values(data, at);
      }
  });
}

}  // namespace

std::vector<Declaration> shard_datasets() {
  const Part p = Part::shard;
  auto text = [](std::string ShardResults::*field) {
    return from_shard([field](const ShardResults& s, Emitter& out) { out.text(s.*field); });
  };
  return {
      attribute(p, "/shard@realizations", "",
                "the realizations of each ensemble it holds, A:B (half-open) or all", "",
                text(&ShardResults::realizations)),
      attribute(p, "/shard@variants", "", "the variants of a sweep it holds, A:B or all", "",
                text(&ShardResults::variants)),
      attribute(p, "/shard@overrides", "", "the --set overrides, as a JSON list", "",
                from_shard([](const ShardResults& s, Emitter& out) {
                  out.text(nlohmann::json(s.overrides).dump());
                })),
      attribute(p, "/shard@ranks", "1", "processes of the MPI job that computed it", "",
                from_shard([](const ShardResults& s, Emitter& out) { out.number(s.parallel.ranks); })),
      attribute(p, "/shard@threads", "1", "threads of each process", "",
                from_shard([](const ShardResults& s, Emitter& out) {
                  out.number(static_cast<double>(s.parallel.threads));
                })),
      attribute(p, "/shard@wall_seconds", "s", "wall-clock time of its realizations", "",
                from_shard([](const ShardResults& s, Emitter& out) { out.number(s.wall_seconds); })),
      dataset(p, "/shard/{e}/{k}/{field}", "",
              "the record of realization k of ensemble e (a sweep's variant): stop (reason code, time, "
              "position), "
              "collisions (high and low 32 bits), wall_seconds, initial_temperature (its bodies' temperature "
              "as it drew them)",
              "", fields_of_depth(1, 0)),
      dataset(
          p, "/shard/{e}/{k}/{group}/{field}", "",
          "its series (t, T, ...: the columns of /particles), histogram (shape = zmax and bins, t, density), "
          "final clusters (clusters/x, v, m, as particles.final_clusters says); for realization 0 also its "
          "final state (final/x, v, m) and space-time record (spacetime/labels, "
          "t, x)",
          "", fields_of_depth(2, 0)),
      dataset(p, "/shard/{e}/{k}/snapshots/{i}/{field}", "", "realization 0's snapshot i (t, x, v, m)",
              "at particles.snapshots", fields_of_depth(3, 1)),
  };
}

std::vector<Declaration> shard_keys() {
  const Part p = Part::shard;
  return {
      key(p, "shard.realizations", "", "the realizations of each ensemble it holds (A:B or all)", "",
          from_shard([](const ShardResults& s, Emitter& out) { out.json(s.realizations); })),
      key(p, "shard.variants", "", "the variants of a sweep it holds (A:B or all)", "",
          from_shard([](const ShardResults& s, Emitter& out) { out.json(s.variants); })),
      key(p, "shard.records", "1", "realizations it holds", "",
          from_shard([](const ShardResults& s, Emitter& out) { out.json(s.records.size()); })),
      key(p, "shard.ranks", "1", "processes of the MPI job that computed it", "",
          from_shard([](const ShardResults& s, Emitter& out) { out.json(s.parallel.ranks); })),
      key(p, "shard.threads", "1", "threads of each process", "",
          from_shard([](const ShardResults& s, Emitter& out) { out.json(s.parallel.threads); })),
  };
}

}  // namespace shockgas::app::layout
