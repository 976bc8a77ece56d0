#include "shockgas/app/files/own_checksum.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstring>
#include <string_view>

#include "shockgas/app/files/sha256.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::app {

namespace fs = std::filesystem;

namespace {

constexpr std::string_view kTag = "shockgas sha256 ";
constexpr std::array<unsigned char, 8> kHdf5Signature = {0x89, 'H', 'D', 'F', '\r', '\n', 0x1a, '\n'};

using Block = std::array<char, kOwnChecksumBytes>;

struct Fd {
  int fd;
  ~Fd() {
    if (fd >= 0) ::close(fd);
  }
};

RunError cannot(const char* what, const fs::path& file) {
  return RunError(std::string("cannot ") + what + " " + file.string() + ": " + std::strerror(errno));
}

// The block's text line for the bytes after it.
std::string line_of(const fs::path& file) {
  const std::uint64_t rest = fs::file_size(file) - kOwnChecksumBytes;
  return std::string(kTag) + sha256_of_file(file, kOwnChecksumBytes) + " " + std::to_string(rest) + "\n";
}

}  // namespace

void write_own_checksum(const fs::path& file) {
  if (fs::file_size(file) < kOwnChecksumBytes)
    throw RunError(file.string() + " is shorter than its checksum block");
  Block block{};
  const std::string line = line_of(file);
  std::memcpy(block.data(), line.data(), line.size());
  const Fd out{::open(file.c_str(), O_WRONLY | O_CLOEXEC)};
  if (out.fd < 0) throw cannot("write", file);
  if (::pwrite(out.fd, block.data(), block.size(), 0) != static_cast<ssize_t>(block.size()))
    throw cannot("write", file);
}

bool starts_with_own_checksum(const fs::path& file) {
  std::array<char, kTag.size()> head{};
  const Fd in{::open(file.c_str(), O_RDONLY | O_CLOEXEC)};
  return in.fd >= 0 && ::pread(in.fd, head.data(), head.size(), 0) == static_cast<ssize_t>(head.size()) &&
         std::string_view(head.data(), head.size()) == kTag;
}

OwnChecksumCheck check_own_checksum(const fs::path& file) {
  Block block{};
  {
    const Fd in{::open(file.c_str(), O_RDONLY | O_CLOEXEC)};
    if (in.fd < 0) throw cannot("read", file);
    const ssize_t n = ::pread(in.fd, block.data(), block.size(), 0);
    if (n < 0) throw cannot("read", file);
    if (n >= 8 && std::memcmp(block.data(), kHdf5Signature.data(), 8) == 0) return {OwnChecksum::absent, ""};
    if (n < static_cast<ssize_t>(block.size()))
      return {OwnChecksum::damaged, "shorter than its checksum block"};
  }
  const std::string recorded(block.data(), strnlen(block.data(), block.size()));
  if (recorded.rfind(kTag, 0) != 0 || recorded.back() != '\n')
    return {OwnChecksum::damaged, "its checksum block (its first 512 bytes) is not as shockgas writes it"};
  for (std::size_t i = recorded.size(); i < block.size(); ++i)
    if (block[i] != 0) return {OwnChecksum::damaged, "its checksum block holds bytes after its text"};
  if (recorded != line_of(file))
    return {OwnChecksum::damaged,
            "its SHA-256 or size differs from the one its first 512 bytes recorded when it was written"};
  return {OwnChecksum::sound, ""};
}

}  // namespace shockgas::app
