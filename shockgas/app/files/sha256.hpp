#pragma once
// SHA-256 of a file, by OpenSSL's libcrypto (the EVP interface): the checksum
// the manifest of a run directory records (manifest.hpp).
#include <cstdint>
#include <filesystem>
#include <string>

namespace shockgas::app {

// The SHA-256 of the file's bytes (those from byte `from` on) as 64 lowercase
// hex digits. The file is read in blocks (never whole); RunError if it cannot be read.
std::string sha256_of_file(const std::filesystem::path& path, std::uint64_t from = 0);

// The SHA-256 of bytes in memory, as above (tests, and small texts).
std::string sha256_of_text(const std::string& bytes);

}  // namespace shockgas::app
