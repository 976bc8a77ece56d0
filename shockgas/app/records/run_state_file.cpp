// The state file of a running realization (run_state_file.hpp): its atomic,
// streamed write and its checked read.
#include "shockgas/app/records/run_state_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

#include "shockgas/app/files/byte_buffer.hpp"
#include "shockgas/app/files/durable_file.hpp"
#include "shockgas/app/files/stream_hash.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::app {

namespace fs = std::filesystem;

namespace {

constexpr const char* kMagic = "shockgas run state\n";
constexpr const char* kPrefix = "checkpoint.run-";
constexpr std::size_t kBuffer = std::size_t{4} << 20;

// Buffered writes to fd, hashed; the first error is kept (errno) and later writes skipped.
class FileOut : public particles::RunStateWriter {
 public:
  explicit FileOut(int fd) : fd_(fd) { buffer_.reserve(kBuffer); }
  void write(const void* data, std::size_t bytes) override {
    const char* p = static_cast<const char*>(data);
    hash_.add(p, bytes);
    if (bytes >= kBuffer) return flush(), put(p, bytes);
    if (buffer_.size() + bytes > kBuffer) flush();
    buffer_.append(p, bytes);
  }
  void flush() {
    put(buffer_.data(), buffer_.size());
    buffer_.clear();
  }
  std::uint64_t hash() const { return hash_.value(); }
  int error() const { return error_; }

 private:
  void put(const char* p, std::size_t n) {
    while (n > 0 && error_ == 0) {
      const ssize_t w = ::write(fd_, p, std::min<std::size_t>(n, std::size_t{1} << 30));
      if (w < 0 && errno == EINTR) continue;
      if (w <= 0) error_ = w < 0 ? errno : ENOSPC;
      if (w > 0) p += w, n -= static_cast<std::size_t>(w);
    }
  }
  int fd_;
  std::string buffer_;
  StreamHash hash_;
  int error_ = 0;
};

// Buffered reads of a file's first `end` bytes; RunError past them.
class FileIn : public particles::RunStateReader {
 public:
  FileIn(const fs::path& file, std::uint64_t end)
      : file_(file), end_(end), fd_(::open(file.c_str(), O_RDONLY)) {
    if (fd_ < 0) throw RunError("cannot open " + file.string() + ": " + std::strerror(errno));
  }
  ~FileIn() override { ::close(fd_); }
  FileIn(const FileIn&) = delete;
  FileIn& operator=(const FileIn&) = delete;

  void read(void* data, std::size_t bytes) override {
    if (bytes > remaining()) throw RunError(file_.string() + ": cut short");
    char* p = static_cast<char*>(data);
    const std::size_t buffered = std::min(bytes, buffer_.size() - at_);
    std::memcpy(p, buffer_.data() + at_, buffered);
    at_ += buffered, p += buffered, bytes -= buffered, used_ += buffered;
    if (bytes == 0) return;
    if (bytes >= kBuffer) return fill(p, bytes), void(used_ += bytes);
    buffer_.resize(std::min<std::uint64_t>(kBuffer, end_ - used_));
    fill(buffer_.data(), buffer_.size());
    std::memcpy(p, buffer_.data(), bytes);
    at_ = bytes, used_ += bytes;
  }
  std::size_t remaining() const override { return static_cast<std::size_t>(end_ - used_); }
  std::string text() {
    const auto n = u64();
    if (n > remaining()) throw RunError(file_.string() + ": cut short");
    std::string s(n, '\0');
    read(s.data(), s.size());
    return s;
  }
  std::uint64_t u64() {
    std::uint64_t x;
    read(&x, sizeof x);
    return x;
  }
  double number() {
    double x;
    read(&x, sizeof x);
    return x;
  }

 private:
  // Exactly n bytes from the file, which holds them (end_ <= its size).
  void fill(char* p, std::size_t n) {
    while (n > 0) {
      const ssize_t r = ::read(fd_, p, std::min<std::size_t>(n, std::size_t{1} << 30));
      if (r < 0 && errno == EINTR) continue;
      if (r <= 0) throw RunError(file_.string() + ": cut short");
      p += r, n -= static_cast<std::size_t>(r);
    }
  }
  fs::path file_;
  std::uint64_t end_;
  int fd_;
  std::string buffer_;
  std::size_t at_ = 0;      // in buffer_
  std::uint64_t used_ = 0;  // bytes handed out
};

InputError damaged(const fs::path& file, const std::string& what) {
  return InputError("--resume", to_text(file.string()),
                    "a realization's state saved by `shockgas run` (this one is damaged: " + what +
                        "; it is left as it is)");
}

RunStateHeader read_header(FileIn& in, const fs::path& file) {
  if (in.text() != kMagic) throw damaged(file, "not a shockgas run state");
  if (const auto format = in.u64(); format != kRunStateFormat)
    throw damaged(file, "format " + std::to_string(format) + ", this build reads format " +
                            std::to_string(kRunStateFormat));
  RunStateHeader h;
  h.version = in.text(), h.commit = in.text(), h.resolved = in.text();
  h.ensemble = in.u64(), h.index = in.u64();
  h.time = in.number(), h.fraction = in.number();
  h.sink = in.text();
  return h;
}

std::uint64_t size_of(const fs::path& file) {
  std::error_code ec;
  const auto size = fs::file_size(file, ec);
  return ec ? 0 : size;
}

// The header of a state file; InputError (damaged) where it cannot be read.
RunStateHeader header_of(const fs::path& file) {
  try {
    FileIn in(file, size_of(file));
    return read_header(in, file);
  } catch (const RunError& e) {
    throw damaged(file, e.what());
  }
}

// Hashes the first `end` bytes of file.
std::uint64_t hash_of(const fs::path& file, std::uint64_t end) {
  FileIn in(file, end);
  StreamHash hash;
  std::string chunk;
  while (in.remaining() > 0) {
    chunk.resize(std::min<std::size_t>(kBuffer, in.remaining()));
    in.read(chunk.data(), chunk.size());
    hash.add(chunk.data(), chunk.size());
  }
  return hash.value();
}

}  // namespace

bool is_run_state_file(const fs::path& name) {
  const std::string text = name.string();
  return text.rfind(kPrefix, 0) == 0 && text.size() > 4 && text.compare(text.size() - 4, 4, ".bin") == 0;
}

fs::path run_state_path(const fs::path& dir, std::uint64_t ensemble, std::uint64_t index) {
  return dir / (kPrefix + std::to_string(ensemble) + "-" + std::to_string(index) + ".bin");
}

void write_run_state(const fs::path& dir, const RunStateHeader& header,
                     const std::function<void(particles::RunStateWriter&)>& write) {
  const fs::path file = run_state_path(dir, header.ensemble, header.index);
  const fs::path temporary = file.string() + ".partial-" + std::to_string(::getpid());
  const int fd = open_new_file(temporary);
  int error = fd < 0 ? errno : 0;
  if (fd >= 0) {
    FileOut out(fd);
    ByteWriter head;
    head.text(kMagic), head.u64(kRunStateFormat);
    head.text(header.version), head.text(header.commit), head.text(header.resolved);
    head.u64(header.ensemble), head.u64(header.index);
    out.write(head.bytes().data(), head.bytes().size());
    out.write(&header.time, sizeof header.time), out.write(&header.fraction, sizeof header.fraction);
    ByteWriter sink;
    sink.text(header.sink);
    out.write(sink.bytes().data(), sink.bytes().size());
    write(out);
    const std::uint64_t sum = out.hash();
    out.write(&sum, sizeof sum);
    out.flush();
    error = out.error();
    if (error == 0 && ::fsync(fd) != 0) error = errno;
    if (::close(fd) != 0 && error == 0) error = errno;
  }
  if (error == 0 && ::rename(temporary.c_str(), file.c_str()) != 0) error = errno;
  if (error != 0) {
    std::error_code ec;
    fs::remove(temporary, ec);
    throw RunError("cannot write the checkpoint " + file.string() + ": " + std::strerror(error));
  }
  try_sync_directory(dir);
}

std::vector<RunStateHeader> read_run_state_headers(const fs::path& dir) {
  std::vector<RunStateHeader> out;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    if (is_run_state_file(entry.path().filename())) out.push_back(header_of(entry.path()));
  }
  return out;
}

std::optional<RunStateHeader> read_run_state_header(const fs::path& file) {
  std::error_code ec;
  if (!fs::is_regular_file(file, ec)) return std::nullopt;
  return header_of(file);
}

void check_run_state(const fs::path& file) {
  const std::uint64_t size = size_of(file);
  if (size < sizeof(std::uint64_t)) throw damaged(file, "cut short");
  const std::uint64_t body = size - sizeof(std::uint64_t);
  try {
    std::uint64_t sum = 0;  // the stored checksum: the last 8 bytes
    const int fd = ::open(file.c_str(), O_RDONLY);
    const bool got = fd >= 0 && ::pread(fd, &sum, sizeof sum, static_cast<off_t>(body)) == sizeof sum;
    if (fd >= 0) ::close(fd);
    if (!got) throw RunError("cannot read its checksum");
    if (hash_of(file, body) != sum) throw damaged(file, "its checksum does not match its contents");
  } catch (const RunError& e) {
    throw damaged(file, e.what());
  }
}

std::unique_ptr<particles::RunStateReader> open_run_state(const fs::path& file, bool checked) {
  if (!checked) check_run_state(file);
  try {
    auto in = std::make_unique<FileIn>(file, size_of(file) - sizeof(std::uint64_t));
    read_header(*in, file);
    return in;
  } catch (const RunError& e) {
    throw damaged(file, e.what());
  }
}

void remove_run_states(const fs::path& dir) {
  std::error_code ec;
  std::vector<fs::path> doomed;
  for (const auto& entry : fs::directory_iterator(dir, ec))
    if (entry.path().filename().string().rfind(kPrefix, 0) == 0) doomed.push_back(entry.path());
  for (const auto& p : doomed) fs::remove(p, ec);
}

}  // namespace shockgas::app
