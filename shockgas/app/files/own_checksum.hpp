#pragma once
// A file's own checksum, in its first kOwnChecksumBytes bytes: the SHA-256 of
// every byte after them, and their count, as one line of text padded with
// zero bytes,
//
//   "shockgas sha256 <64 hex digits> <bytes after the block>\n" 0 0 0 ...
//
// so that a copy of the file, away from the manifest of its directory, can
// tell that it is damaged wherever the damage lies: in data, in metadata, in
// unused bytes, or in the block itself. result.h5 keeps it in its HDF5 user
// block (HDF5 File Format Specification, II.A: the library skips it and
// finds the superblock at byte 512).
#include <cstdint>
#include <filesystem>
#include <string>

namespace shockgas::app {

inline constexpr std::uint64_t kOwnChecksumBytes = 512;

// Writes the block of `file` (whose first kOwnChecksumBytes bytes are the
// program's to fill) from the bytes after it; RunError if it cannot.
void write_own_checksum(const std::filesystem::path& file);

enum class OwnChecksum {
  absent,  // the file starts with the HDF5 signature: no block (layout 1.0)
  sound,   // the block holds the SHA-256 and the size of the rest, as they are
  damaged  // anything else
};

struct OwnChecksumCheck {
  OwnChecksum state = OwnChecksum::absent;
  std::string detail;  // what differs, for a damaged file
};

// Whether `file` starts as the block does ("shockgas sha256 "): a file of
// shockgas's, whatever damage lies after those bytes.
bool starts_with_own_checksum(const std::filesystem::path& file);

// Checks the block of `file`, reading the whole file; RunError if it cannot be read.
OwnChecksumCheck check_own_checksum(const std::filesystem::path& file);

}  // namespace shockgas::app
