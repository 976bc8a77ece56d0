#include "manifest.hpp"

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "durable_file.hpp"
#include "sha256.hpp"
#include "shockgas/core/error.hpp"
#include "shockgas/version.hpp"

namespace shockgas::app {

namespace fs = std::filesystem;
using nlohmann::ordered_json;

namespace {

constexpr const char* kFormat = "shockgas run directory 1";
constexpr std::uintmax_t kMaxManifestBytes = 64u << 20;  // far above any run's list of files

[[noreturn]] void refuse(const fs::path& file, const std::string& why) {
  throw InputError("manifest", to_text(file.string()), "a manifest.json written by shockgas (" + why + ")");
}

ManifestEntry entry_of(const ordered_json& j, const fs::path& file) {
  if (!j.is_object() || !j.contains("path") || !j["path"].is_string() || !j.contains("bytes") ||
      !j["bytes"].is_number_unsigned() || !j.contains("sha256") || !j["sha256"].is_string())
    refuse(file, "each file with path, bytes and sha256");
  return {j["path"].get<std::string>(), j["bytes"].get<std::uint64_t>(), j["sha256"].get<std::string>()};
}

}  // namespace

const ManifestEntry* Manifest::find(const std::string& relative_path) const {
  for (const auto& f : files)
    if (f.path == relative_path) return &f;
  return nullptr;
}

Manifest write_manifest(const fs::path& dir, const std::string& scene) {
  Manifest m;
  m.scene = scene;
  for (const auto& entry : fs::recursive_directory_iterator(dir)) {
    if (!entry.is_regular_file() || entry.path() == dir / kManifestFile) continue;
    m.files.push_back({fs::relative(entry.path(), dir).generic_string(), entry.file_size(),
                       sha256_of_file(entry.path())});
  }
  std::sort(m.files.begin(), m.files.end(), [](const auto& a, const auto& b) { return a.path < b.path; });
  ordered_json j;
  j["format"] = kFormat;
  j["scene"] = scene;
  j["shockgas_version"] = kVersion;
  j["git_commit"] = kGitCommit;
  j["files"] = ordered_json::array();
  for (const auto& f : m.files) j["files"].push_back({{"path", f.path}, {"bytes", f.bytes}, {"sha256", f.sha256}});
  write_file(dir / kManifestFile, j.dump(2) + "\n");
  return m;
}

std::optional<Manifest> read_manifest(const fs::path& dir) {
  const fs::path file = dir / kManifestFile;
  std::error_code ec;
  const auto status = fs::status(file, ec);
  if (status.type() == fs::file_type::not_found) return std::nullopt;
  if (status.type() != fs::file_type::regular) refuse(file, "not a regular file");
  if (fs::file_size(file, ec) > kMaxManifestBytes) refuse(file, "too large");
  std::ifstream in(file);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in) refuse(file, "unreadable");
  const ordered_json j = ordered_json::parse(text.str(), nullptr, false);
  if (j.is_discarded() || !j.is_object()) refuse(file, "not JSON");
  if (!j.contains("format") || j["format"] != kFormat) refuse(file, "format \"" + std::string(kFormat) + "\"");
  if (!j.contains("scene") || !j["scene"].is_string() || !j.contains("files") || !j["files"].is_array())
    refuse(file, "scene and files");
  Manifest m;
  m.scene = j["scene"].get<std::string>();
  for (const auto& f : j["files"]) m.files.push_back(entry_of(f, file));
  return m;
}

}  // namespace shockgas::app
