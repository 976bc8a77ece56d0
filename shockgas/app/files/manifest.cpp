#include "shockgas/app/files/manifest.hpp"

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <unordered_set>

#include "shockgas/app/files/durable_file.hpp"
#include "shockgas/app/files/file_problem.hpp"
#include "shockgas/app/files/sha256.hpp"
#include "shockgas/core/error.hpp"
#include "shockgas/version.hpp"

namespace shockgas::app {

namespace fs = std::filesystem;
using nlohmann::ordered_json;

namespace {

constexpr const char* kFormat = "shockgas run directory 1";
constexpr std::uintmax_t kMaxManifestBytes = 64u << 20;  // far above any run's list of files

[[noreturn]] void refuse(const fs::path& file, const std::string& why) {
  throw FileProblem("manifest", file.string(), "not a manifest.json written by shockgas", why);
}

// A path as write_manifest writes it: relative, '/'-separated, no empty, "." or
// ".." part (nothing outside the directory, one spelling per file).
bool normal_relative(const std::string& path) {
  if (path.empty() || path.front() == '/') return false;
  for (std::size_t from = 0; from <= path.size();) {
    const std::size_t to = std::min(path.find('/', from), path.size());
    const std::string part = path.substr(from, to - from);
    if (part.empty() || part == "." || part == "..") return false;
    from = to + 1;
  }
  return true;
}

bool hex_digest(const std::string& s) {
  return s.size() == 64 && std::all_of(s.begin(), s.end(), [](char c) {
           return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f');
         });
}

ManifestEntry entry_of(const ordered_json& j, const fs::path& file) {
  if (!j.is_object() || !j.contains("path") || !j["path"].is_string() || !j.contains("bytes") ||
      !j["bytes"].is_number_unsigned() || !j.contains("sha256") || !j["sha256"].is_string())
    refuse(file, "each file with path, bytes and sha256");
  ManifestEntry e{j["path"].get<std::string>(), j["bytes"].get<std::uint64_t>(),
                  j["sha256"].get<std::string>()};
  if (!normal_relative(e.path))
    refuse(file, "a path outside its directory or not in normal form: \"" + e.path + "\"");
  if (!hex_digest(e.sha256)) refuse(file, "a SHA-256 that is not 64 lowercase hex digits, for " + e.path);
  return e;
}

}  // namespace

const ManifestEntry* Manifest::find(const std::string& relative_path) const {
  for (const auto& f : files)
    if (f.path == relative_path) return &f;
  return nullptr;
}

namespace {

// Every regular file under dir (links not followed, none listed), with its
// path relative to dir, the manifest of dir itself excepted.
void add_files(const fs::path& dir, std::vector<ManifestEntry>& files) {
  for (const auto& entry : fs::recursive_directory_iterator(dir)) {
    if (entry.is_symlink() || !entry.is_regular_file() || entry.path() == dir / kManifestFile) continue;
    files.push_back({entry.path().lexically_relative(dir).generic_string(), entry.file_size(),
                     sha256_of_file(entry.path())});
  }
}

// The text of m, its files sorted by path.
std::string manifest_text(Manifest& m) {
  std::sort(m.files.begin(), m.files.end(), [](const auto& a, const auto& b) { return a.path < b.path; });
  ordered_json j;
  j["format"] = kFormat;
  j["scene"] = m.scene;
  j["shockgas_version"] = kVersion;
  j["git_commit"] = kGitCommit;
  j["files"] = ordered_json::array();
  for (const auto& f : m.files)
    j["files"].push_back({{"path", f.path}, {"bytes", f.bytes}, {"sha256", f.sha256}});
  return j.dump(2) + "\n";
}

}  // namespace

Manifest write_manifest(const fs::path& dir, const std::string& scene) {
  Manifest m;
  m.scene = scene;
  add_files(dir, m.files);
  replace_file(dir / kManifestFile, manifest_text(m));
  return m;
}

void update_manifest(const fs::path& dir, const std::string& sub, const Manifest& of_sub) {
  std::optional<Manifest> m = read_manifest(dir);
  if (!m) return;
  const std::string prefix = sub + "/";
  std::erase_if(m->files, [&](const ManifestEntry& e) { return e.path.rfind(prefix, 0) == 0; });
  for (const ManifestEntry& e : of_sub.files) m->files.push_back({prefix + e.path, e.bytes, e.sha256});
  const fs::path own = dir / sub / kManifestFile;  // the one file of sub its manifest does not list
  m->files.push_back({prefix + kManifestFile, fs::file_size(own), sha256_of_file(own)});
  replace_file(dir / kManifestFile, manifest_text(*m));
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
  if (j.is_discarded()) refuse(file, "not JSON");
  if (!j.is_object()) refuse(file, std::string("JSON, but ") + j.type_name() + ", not an object");
  if (!j.contains("format") || j["format"] != kFormat)
    refuse(file, "format \"" + std::string(kFormat) + "\"");
  if (!j.contains("scene") || !j["scene"].is_string() || !j.contains("files") || !j["files"].is_array())
    refuse(file, "scene and files");
  Manifest m;
  m.scene = j["scene"].get<std::string>();
  std::unordered_set<std::string> seen;
  for (const auto& f : j["files"]) {
    m.files.push_back(entry_of(f, file));
    if (!seen.insert(m.files.back().path).second) refuse(file, "a file listed twice: " + m.files.back().path);
  }
  // Every run that writes result.h5 writes summary.json and report.md beside it.
  for (const ManifestEntry& e : m.files) {
    const std::string at = e.path.substr(0, e.path.size() - fs::path(e.path).filename().string().size());
    if (fs::path(e.path).filename() != "result.h5") continue;
    for (const char* beside : {"summary.json", "report.md"})
      if (!seen.count(at + beside))
        refuse(file, "a list of every file of its run (it lists " + e.path + " without " + at + beside + ")");
  }
  return m;
}

}  // namespace shockgas::app
