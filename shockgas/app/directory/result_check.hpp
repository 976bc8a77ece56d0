#pragma once
// What every reader in shockgas checks before the HDF5 library touches a
// result file: the library cannot be trusted to reject a damaged file (it may
// crash inside it), so a file is compared with the size and SHA-256 that the
// run directory's manifest.json recorded when it was written (manifest.hpp),
// and with its own checksum, which it carries wherever it is copied
// (own_checksum.hpp; files of layout 2.0 on).
#include <filesystem>
#include <string>
#include <vector>

#include "shockgas/app/files/file_problem.hpp"
#include "shockgas/app/files/manifest.hpp"

namespace shockgas::app {

// A result file a reader refuses: FileProblem with key "RESULT" and the problem
// "no such file", "a directory", "not a regular file", "empty", "truncated",
// "damaged", "not an HDF5 file", "unreadable" or "too large to read".
inline FileProblem result_problem(const std::string& path, const std::string& problem,
                                  const std::string& detail) {
  return FileProblem("RESULT", path, problem, detail);
}

enum class Verification {
  manifest,      // size and SHA-256 equal to the manifest's record (a file without its own checksum)
  own_checksum,  // its own checksum verified (and the manifest's record, where one lists it)
  no_manifest,   // neither: no own checksum (layout 1.0), and no manifest.json beside it that lists it
  damaged,       // it failed a checksum: read only to name where the damage lies (info)
};
// Checked against its manifest or its own checksum.
inline bool verified(Verification v) {
  return v == Verification::manifest || v == Verification::own_checksum;
}

// The result file a path names: the path itself, or the result.h5 inside a run
// directory. FileProblem for a directory without one.
std::filesystem::path result_file_of(const std::filesystem::path& path);

// Checks a result file before it is opened: FileProblem when it is missing,
// not a regular file, empty, shorter or other than its manifest's record, left
// out of the manifest beside it, other than its own checksum records
// ("damaged"), or without the HDF5 signature. One verdict for both checks:
// own_checksum where the file carries one (and the manifest agrees, if it lists
// the file), else manifest where the manifest lists it, else no_manifest.
Verification check_result_file(const std::filesystem::path& file);

inline constexpr const char* kLeftOut = "left out of manifest.json";

// One file of a run directory checked against its manifest.json.
struct FileState {
  std::string path;  // relative to the directory, as listed
  // Empty: intact. Else "missing", "truncated", "damaged", "not a regular
  // file", "unreadable", kLeftOut (a file of a name a run writes, which the
  // manifest does not list: it was edited), or "not listed" (any other file or
  // link the manifest does not list, which is no difference).
  std::string problem;
  std::string detail;
  bool intact() const { return problem.empty(); }
};

// Every file the manifest of dir lists, in its order, by size and SHA-256 (the
// listed path `skip`, already checked, is taken as intact), then every regular
// file and link under dir that it does not list (an interrupted run's
// checkpoint named as one).
std::vector<FileState> check_listed_files(const std::filesystem::path& dir, const Manifest& manifest,
                                          const std::filesystem::path& skip);

// "summary.json damaged, fields.png missing": the listed files that are not as
// recorded ("" when all are; files not listed are no difference).
std::string differences_of(const std::vector<FileState>& states);

// The warning a reader gives for Verification::no_manifest.
std::string unverified_warning(const std::filesystem::path& file);

}  // namespace shockgas::app
