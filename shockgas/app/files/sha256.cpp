#include "shockgas/app/files/sha256.hpp"

#include <fcntl.h>
#include <openssl/evp.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <memory>
#include <vector>

#include "shockgas/core/error.hpp"

namespace shockgas::app {

namespace {

struct DigestFree {
  void operator()(EVP_MD_CTX* ctx) const { EVP_MD_CTX_free(ctx); }
};
using Digest = std::unique_ptr<EVP_MD_CTX, DigestFree>;

Digest start_digest() {
  Digest ctx(EVP_MD_CTX_new());
  if (!ctx || EVP_DigestInit_ex(ctx.get(), EVP_sha256(), nullptr) != 1)
    throw RunError("SHA-256: OpenSSL init failed");
  return ctx;
}

std::string finish_digest(EVP_MD_CTX* ctx) {
  unsigned char md[EVP_MAX_MD_SIZE];
  unsigned int size = 0;
  if (EVP_DigestFinal_ex(ctx, md, &size) != 1) throw RunError("SHA-256: OpenSSL final failed");
  static const char* hex = "0123456789abcdef";
  std::string out;
  for (unsigned int i = 0; i < size; ++i) out += {hex[md[i] >> 4], hex[md[i] & 15]};
  return out;
}

struct Fd {
  int fd;
  ~Fd() {
    if (fd >= 0) close(fd);
  }
};

}  // namespace

std::string sha256_of_file(const std::filesystem::path& path, std::uint64_t from) {
  Fd file{open(path.c_str(), O_RDONLY | O_CLOEXEC)};
  if (file.fd < 0) throw RunError("cannot read " + path.string() + ": " + std::strerror(errno));
  if (from > 0 && lseek(file.fd, static_cast<off_t>(from), SEEK_SET) < 0)
    throw RunError("cannot read " + path.string() + ": " + std::strerror(errno));
  Digest ctx = start_digest();
  std::vector<char> block(1 << 20);
  for (;;) {
    const ssize_t n = read(file.fd, block.data(), block.size());
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw RunError("cannot read " + path.string() + ": " + std::strerror(errno));
    if (n == 0) break;
    if (EVP_DigestUpdate(ctx.get(), block.data(), static_cast<std::size_t>(n)) != 1)
      throw RunError("SHA-256: OpenSSL update failed");
  }
  return finish_digest(ctx.get());
}

std::string sha256_of_text(const std::string& bytes) {
  Digest ctx = start_digest();
  if (EVP_DigestUpdate(ctx.get(), bytes.data(), bytes.size()) != 1)
    throw RunError("SHA-256: OpenSSL update failed");
  return finish_digest(ctx.get());
}

}  // namespace shockgas::app
