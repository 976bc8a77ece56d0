#include "shockgas/app/directory/result_check.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstring>

#include "shockgas/app/directory/run_directory.hpp"
#include "shockgas/app/directory/run_target.hpp"
#include "shockgas/app/files/durable_file.hpp"
#include "shockgas/app/files/manifest.hpp"
#include "shockgas/app/files/own_checksum.hpp"
#include "shockgas/app/files/sha256.hpp"
#include "shockgas/app/records/checkpoint.hpp"

namespace shockgas::app {

namespace fs = std::filesystem;

namespace {

// The HDF5 format signature; the superblock starts at 0 or, after a user
// block, at 512, 1024, 2048, ... bytes (HDF5 File Format Specification, II.A).
constexpr std::array<unsigned char, 8> kSignature = {0x89, 'H', 'D', 'F', '\r', '\n', 0x1a, '\n'};

bool has_hdf5_signature(const fs::path& file, std::uint64_t size) {
  const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw result_problem(file.string(), "unreadable", std::strerror(errno));
  bool found = false;
  for (std::uint64_t at = 0; !found && at + kSignature.size() <= size; at = at == 0 ? 512 : 2 * at) {
    std::array<unsigned char, 8> head{};
    found =
        ::pread(fd, head.data(), head.size(), static_cast<off_t>(at)) == static_cast<ssize_t>(head.size()) &&
        head == kSignature;
  }
  ::close(fd);
  return found;
}

// What differs between a file of `size` bytes and its entry in `manifest`:
// nothing, "truncated", "damaged" or "unreadable", with the detail.
FileState difference(const ManifestEntry& e, const fs::path& file, std::uint64_t size,
                     const fs::path& manifest) {
  if (size < e.bytes)
    return {e.path, "truncated",
            std::to_string(size) + " of the " + std::to_string(e.bytes) + " bytes " + manifest.string() +
                " recorded when the run wrote it"};
  std::string digest;
  try {
    digest = size == e.bytes ? sha256_of_file(file) : "";
  } catch (const std::exception& error) {
    return {e.path, "unreadable", error.what()};
  }
  if (digest != e.sha256)
    return {e.path, "damaged",
            "its SHA-256 differs from the one " + manifest.string() +
                " recorded when the run wrote it; run the scene again"};
  return {e.path, "", ""};
}

void check_against(const ManifestEntry& e, const fs::path& file, std::uint64_t size) {
  const FileState state = difference(e, file, size, file.parent_path() / kManifestFile);
  if (!state.intact()) throw result_problem(file.string(), state.problem, state.detail);
}

// A file that carries its own checksum is checked against it (own_checksum):
// FileProblem "damaged" where it differs. One without is as `otherwise` says.
Verification check_own(const fs::path& file, Verification otherwise) {
  OwnChecksumCheck own;
  try {
    own = check_own_checksum(file);
  } catch (const std::exception& error) {
    throw result_problem(file.string(), "unreadable", error.what());
  }
  if (own.state == OwnChecksum::damaged) throw result_problem(file.string(), "damaged", own.detail);
  return own.state == OwnChecksum::sound ? Verification::own_checksum : otherwise;
}

FileState listed_file_state(const fs::path& dir, const ManifestEntry& e) {
  const fs::path file = dir / e.path;
  struct stat st {};
  if (::lstat(file.c_str(), &st) != 0)
    return {e.path, errno == ENOENT ? "missing" : "unreadable", errno == ENOENT ? "" : std::strerror(errno)};
  if (!S_ISREG(st.st_mode)) return {e.path, "not a regular file", ""};
  return difference(e, file, static_cast<std::uint64_t>(st.st_size), dir / kManifestFile);
}

// For a missing file: that the manifest beside it lists it, if it does.
std::string listed_note(const fs::path& file) {
  std::optional<Manifest> manifest;
  try {
    manifest = read_manifest(file.parent_path());
  } catch (const std::exception&) {
    return "";
  }
  return manifest && manifest->find(file.filename().string())
             ? "the run wrote it, as " + (file.parent_path() / kManifestFile).string() +
                   " records; it was removed since"
             : "";
}

// A staging directory that a killed command left beside a directory inside
// dir (a sweep's variant, animated): run_directory.hpp.
bool leftover_inside(const fs::path& entry) {
  const std::string name = entry.filename().string();
  const auto tmp = name.find(".tmp-"), old = name.find(".old-");
  const auto at = std::min(tmp, old);
  return name.size() > 1 && name.front() == '.' && at != std::string::npos &&
         is_run_directory_leftover(name, (entry.parent_path() / name.substr(1, at - 1)).string());
}

}  // namespace

fs::path result_file_of(const fs::path& path) {
  std::error_code ec;
  if (!fs::is_directory(path, ec)) return path;
  if (fs::exists(path / "result.h5", ec) || fs::exists(path / kManifestFile, ec)) return path / "result.h5";
  throw result_problem(path.string(), "a directory",
                       "give a result file, or a run directory that holds result.h5 (this one does not)");
}

Verification check_result_file(const fs::path& file) {
  struct stat st {};
  if (::stat(file.c_str(), &st) != 0) {
    if (errno == ENOENT) throw result_problem(file.string(), "no such file", listed_note(file));
    throw result_problem(file.string(), "unreadable", std::strerror(errno));
  }
  if (S_ISDIR(st.st_mode)) return check_result_file(result_file_of(file));
  if (!S_ISREG(st.st_mode))
    throw result_problem(file.string(), "not a regular file", "a device, pipe or socket, not a result file");
  const auto size = static_cast<std::uint64_t>(st.st_size);
  const auto manifest = read_manifest(file.parent_path());
  const ManifestEntry* entry = manifest ? manifest->find(file.filename().string()) : nullptr;
  if (entry) check_against(*entry, file, size);
  // A manifest lists every file of its run: one that leaves this file out was
  // edited (a line taken out exempts nothing), or the file was put there since.
  if (!entry && manifest)
    throw result_problem(file.string(), "not as its manifest.json records",
                         (file.parent_path() / kManifestFile).string() +
                             " does not list it, though a run lists every file it writes");
  if (!entry && size == 0)
    throw result_problem(file.string(), "empty", "0 bytes: the run that wrote it did not finish");
  // Behind a checksum block of its own a missing signature is a damage, named by the block's check.
  if (!entry && !has_hdf5_signature(file, size) && !starts_with_own_checksum(file))
    throw result_problem(file.string(), "not an HDF5 file", "it does not start with the HDF5 signature");
  return check_own(file, entry ? Verification::manifest : Verification::no_manifest);
}

std::vector<FileState> check_listed_files(const fs::path& dir, const Manifest& manifest,
                                          const fs::path& skip) {
  std::vector<FileState> states;
  for (const ManifestEntry& e : manifest.files)
    states.push_back(e.path == skip.generic_string() ? FileState{e.path, "", ""} : listed_file_state(dir, e));
  std::error_code scan;
  for (auto it = fs::recursive_directory_iterator(dir, fs::directory_options::skip_permission_denied, scan);
       !scan && it != fs::recursive_directory_iterator(); it.increment(scan)) {
    const std::string relative = it->path().lexically_relative(dir).generic_string();
    if (relative == kManifestFile || manifest.find(relative)) continue;
    std::error_code ec;  // a file that goes while the scan passes is not a stop of the scan
    if (it->is_symlink(ec)) {
      states.push_back({relative, "not listed", "a symbolic link, which no run writes"});
    } else if (it->is_directory(ec) && leftover_inside(it->path())) {
      states.push_back({relative, "not listed", "left by a command that was killed: the next one clears it"});
      it.disable_recursion_pending();
    } else if (it->is_regular_file(ec)) {
      if (run_in_progress_file(relative))
        states.push_back({relative, "not listed", "an interrupted run's checkpoint" + resume_hint(dir)});
      else if (run_output_name(relative))
        states.push_back({relative, kLeftOut,
                          "a file a run writes, which " + (dir / kManifestFile).string() +
                              " leaves out: the manifest was edited, or the file put there since"});
      else
        states.push_back({relative, "not listed", "not written by the run"});
    }
  }
  return states;
}

std::string differences_of(const std::vector<FileState>& states) {
  std::string text;
  for (const FileState& f : states)
    if (!f.intact() && f.problem != "not listed")  // kLeftOut counts
      text += (text.empty() ? "" : ", ") + f.path + " " + f.problem;
  return text;
}

std::string unverified_warning(const fs::path& file) {
  return file.string() +
         " has no checksum of its own (layout 1.0, written before result files carried one) "
         "and is not listed in a " +
         kManifestFile + " beside it: its integrity cannot be checked";
}

}  // namespace shockgas::app
