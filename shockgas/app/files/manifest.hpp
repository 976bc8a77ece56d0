#pragma once
// manifest.json of a run directory: every file the run wrote, with its size and
// SHA-256, and the scene that wrote them (docs/output.md, "The run directory").
//
// It is written last, over the finished directory, before the directory is
// moved into place; a reader checks a file against it before the HDF5 library
// touches the file (result_check.hpp), and the next run into the directory
// reads from it whose results the directory holds and which files are its own
// (run_target.hpp).
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace shockgas::app {

inline constexpr const char* kManifestFile = "manifest.json";

struct ManifestEntry {
  std::string path;  // relative to the run directory, '/'-separated ("0-r0.5/result.h5")
  std::uint64_t bytes = 0;
  std::string sha256;  // 64 lowercase hex digits
};

struct Manifest {
  std::string scene;  // the scene's name
  std::vector<ManifestEntry> files;
  const ManifestEntry* find(const std::string& relative_path) const;
};

// Each writer below replaces dir/manifest.json whole (replace_file,
// durable_file.hpp): a directory changed in place (`shockgas animate`, a
// shard) never holds half a manifest.
//
// Hashes every regular file under dir (recursively, links not followed, the
// manifest itself excepted) and writes dir/manifest.json; returns what it wrote.
Manifest write_manifest(const std::filesystem::path& dir, const std::string& scene);

// The entries of dir's manifest for the files under dir/sub (a sweep's
// variant) replaced by those of of_sub, the manifest just written for dir/sub
// (its files are not hashed again), and dir/sub/manifest.json itself; the
// others as they were: after a command changed the files of a variant
// (`shockgas animate`). Nothing where dir has no manifest.
void update_manifest(const std::filesystem::path& dir, const std::string& sub, const Manifest& of_sub);

// The manifest of dir, or nullopt where dir has none. A manifest.json that is
// not one shockgas wrote (unreadable, not JSON, wrong fields, a path that is
// not a file of dir in the form written, a malformed digest, a file listed
// twice) is a FileProblem (InputError) naming it.
std::optional<Manifest> read_manifest(const std::filesystem::path& dir);

}  // namespace shockgas::app
