#pragma once
// Two results of one scene compared bit for bit: every dataset and attribute of
// result.h5 and every key of summary.json, in the directory and in each
// subdirectory holding a result (a sweep's variants). Left out, as what may
// differ between two runs of one scene: dates (created_utc), timings
// (wall_seconds, collisions_per_second; as attributes, keys, or a shard's
// per-realization datasets /shard/{e}/{k}/wall_seconds) and how the work was
// spread (parallel.*), and /@attributes_sha256, which digests the dates with the
// rest. Used by the shard tests and, as compare_runs, by the MPI
// and checkpoint tests.
#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "shockgas/app/output/hdf5_file.hpp"

namespace shockgas::app::testing {

inline bool excluded(const std::string& name) {
  return name == "created_utc" || name == "wall_seconds" || name == "collisions_per_second" ||
         name == "parallel" ||
         name == "attributes_sha256";  // the last: a digest of the others, dates included
}

inline void compare_json(const nlohmann::json& a, const nlohmann::json& b, const std::string& at,
                         std::vector<std::string>& out) {
  if (a.is_object() && b.is_object()) {
    std::set<std::string> keys;
    for (auto it = a.begin(); it != a.end(); ++it) keys.insert(it.key());
    for (auto it = b.begin(); it != b.end(); ++it) keys.insert(it.key());
    for (const auto& k : keys) {
      if (excluded(k)) continue;
      if (!a.contains(k) || !b.contains(k))
        out.push_back("summary key " + at + k + " in one only");
      else
        compare_json(a[k], b[k], at + k + ".", out);
    }
  } else if (a.is_array() && b.is_array() && a.size() == b.size()) {
    for (std::size_t i = 0; i < a.size(); ++i) compare_json(a[i], b[i], at + std::to_string(i) + ".", out);
  } else if (a.is_number_float() && b.is_number_float()) {
    const double x = a.get<double>(), y = b.get<double>();
    if (std::bit_cast<std::uint64_t>(x) != std::bit_cast<std::uint64_t>(y))
      out.push_back("summary key " + at + ": " + a.dump() + " vs " + b.dump());
  } else if (a != b) {
    out.push_back("summary key " + at + ": " + a.dump() + " vs " + b.dump());
  }
}

inline std::vector<std::string> objects_of(const std::vector<DatasetInfo>& sets) {
  std::set<std::string> objects{"/"};
  for (const auto& d : sets) {
    objects.insert(d.path);
    for (auto at = d.path.find('/', 1); at != std::string::npos; at = d.path.find('/', at + 1))
      objects.insert(d.path.substr(0, at));
  }
  return {objects.begin(), objects.end()};
}

inline void compare_files(const std::filesystem::path& a, const std::filesystem::path& b,
                          std::vector<std::string>& out) {
  const Hdf5File x = Hdf5File::open(a.string()), y = Hdf5File::open(b.string());
  const auto dx = x.datasets(), dy = y.datasets();
  std::set<std::string> px, py;
  for (const auto& d : dx) px.insert(d.path);
  for (const auto& d : dy) py.insert(d.path);
  if (px != py) out.push_back(a.string() + ": the datasets differ from " + b.string());
  for (const auto& path : px) {
    if (!py.count(path)) continue;
    // A shard keeps each realization's timing as a dataset: /shard/{e}/{k}/wall_seconds.
    if (path.rfind("/shard/", 0) == 0 && excluded(path.substr(path.rfind('/') + 1))) continue;
    const auto u = x.read(path), v = y.read(path);
    if (u.size() != v.size() ||
        (!u.empty() && std::memcmp(u.data(), v.data(), u.size() * sizeof(double)) != 0))
      out.push_back(a.string() + ": dataset " + path + " differs");
  }
  const auto oy = objects_of(dy);
  for (const auto& object : objects_of(dx)) {
    if (std::find(oy.begin(), oy.end(), object) == oy.end()) continue;
    auto ax = x.attributes(object), ay = y.attributes(object);
    std::erase_if(ax, [](const auto& kv) { return excluded(kv.first); });
    std::erase_if(ay, [](const auto& kv) { return excluded(kv.first); });
    if (ax != ay) out.push_back(a.string() + ": the attributes of " + object + " differ");
  }
}

inline nlohmann::json read_json(const std::filesystem::path& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

// The differences, empty when the results agree bit for bit.
inline std::vector<std::string> result_differences(const std::filesystem::path& a,
                                                   const std::filesystem::path& b) {
  std::vector<std::string> out;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(a)) {
    if (entry.path().filename() != "result.h5") continue;
    const auto dir = entry.path().parent_path();
    const auto other = b / std::filesystem::relative(dir, a);
    if (!std::filesystem::exists(other / "result.h5")) {
      out.push_back((other / "result.h5").string() + " is missing");
      continue;
    }
    compare_files(dir / "result.h5", other / "result.h5", out);
    compare_json(read_json(dir / "summary.json"), read_json(other / "summary.json"), "", out);
  }
  if (out.empty() && !std::filesystem::exists(a / "result.h5"))
    out.push_back(a.string() + " holds no result");
  return out;
}

}  // namespace shockgas::app::testing
