#pragma once
// SHA-256 of a file, by OpenSSL's libcrypto (the EVP interface): the checksum
// the manifest of a run directory records (manifest.hpp).
#include <filesystem>
#include <string>

namespace shockgas::app {

// The SHA-256 of the file's bytes as 64 lowercase hex digits. The file is read
// in blocks (never whole); RunError if it cannot be read.
std::string sha256_of_file(const std::filesystem::path& path);

// The SHA-256 of bytes in memory, as above (tests, and small texts).
std::string sha256_of_text(const std::string& bytes);

}  // namespace shockgas::app
