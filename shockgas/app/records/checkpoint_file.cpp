// The checkpoint file (checkpoint.hpp): its bytes, its atomic write and the
// checks that refuse a damaged or foreign one.
#include <fcntl.h>
#include <toml++/toml.h>
#include <unistd.h>

#include <bit>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

#include "shockgas/app/files/byte_buffer.hpp"
#include "shockgas/app/files/durable_file.hpp"
#include "shockgas/app/records/checkpoint.hpp"
#include "shockgas/app/records/run_state_file.hpp"
#include "shockgas/core/error.hpp"
#include "shockgas/version.hpp"

namespace shockgas::app {

namespace fs = std::filesystem;

namespace {

constexpr const char* kMagic = "shockgas checkpoint\n";

// FNV-1a, 64 bits (Fowler, Noll, Vo): a change of any byte changes it.
std::uint64_t fnv1a(const char* data, std::size_t n) {
  std::uint64_t h = 14695981039346656037ull;
  for (std::size_t i = 0; i < n; ++i) h = (h ^ static_cast<unsigned char>(data[i])) * 1099511628211ull;
  return h;
}

std::string to_bytes(const Checkpoint& c) {
  ByteWriter out;
  out.text(kMagic);
  out.u64(kCheckpointFormat);
  for (const std::string* s : {&c.version, &c.commit, &c.scene_path, &c.scene_text}) out.text(*s);
  out.u64(c.overrides.size());
  for (const auto& o : c.overrides) out.text(o);
  for (const std::string* s : {&c.resolved, &c.realizations, &c.variants}) out.text(*s);
  out.u64(c.records.size());
  for (const auto& r : c.records) out.text(encode(r));
  out.u64(std::bit_cast<std::uint64_t>(c.seconds));
  out.u64(fnv1a(out.bytes().data(), out.bytes().size()));
  return out.take();
}

InputError damaged(const fs::path& file, const std::string& what) {
  return InputError(
      "--resume", to_text(file.string()),
      "a checkpoint written by `shockgas run` (this one is damaged: " + what + "; it is left as it is)");
}

Checkpoint from_bytes(const std::string& bytes, const fs::path& file) {
  ByteWriter magic;
  magic.text(kMagic);
  if (bytes.compare(0, magic.bytes().size(), magic.bytes()) != 0)
    throw damaged(file, "not a shockgas checkpoint");
  const std::size_t body = bytes.size() - sizeof(std::uint64_t);
  std::uint64_t sum;
  std::memcpy(&sum, bytes.data() + body, sizeof sum);
  ByteReader in(bytes, "checkpoint " + file.string());
  in.text();  // the magic, checked above
  if (fnv1a(bytes.data(), body) != sum) throw damaged(file, "its checksum does not match its contents");
  if (const auto format = in.u64(); format != kCheckpointFormat)
    throw damaged(file, "format " + std::to_string(format) + ", this build reads format " +
                            std::to_string(kCheckpointFormat));
  Checkpoint c;
  for (std::string* s : {&c.version, &c.commit, &c.scene_path, &c.scene_text}) *s = in.text();
  c.overrides.resize(in.u64());
  for (auto& o : c.overrides) o = in.text();
  for (std::string* s : {&c.resolved, &c.realizations, &c.variants}) *s = in.text();
  c.records.resize(in.u64());
  for (auto& r : c.records) r = decode(in.text());
  c.seconds = std::bit_cast<double>(in.u64());
  if (in.position() != body) throw damaged(file, "bytes after its records");
  return c;
}

std::string read_all(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

// write(2) until every byte is out; false on an error.
bool write_fully(int fd, const std::string& bytes) {
  for (std::size_t at = 0; at < bytes.size();) {
    const ssize_t n = ::write(fd, bytes.data() + at, bytes.size() - at);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    at += static_cast<std::size_t>(n);
  }
  return true;
}

}  // namespace

fs::path checkpoint_path(const fs::path& dir) { return dir / "checkpoint.bin"; }

std::string resume_hint(const fs::path& dir) {
  return "; continue with: shockgas run --resume " + dir.string();
}

bool is_checkpoint_file(const fs::path& name) {
  const std::string text = name.string();
  return text == "checkpoint.bin" || text.rfind("checkpoint.bin.partial-", 0) == 0 ||
         is_run_state_file(name) ||
         (text.rfind("checkpoint.run-", 0) == 0 && text.find(".bin.partial-") != std::string::npos);
}

Checkpoint make_checkpoint(const Scene& scene, const std::string& realizations, const std::string& variants,
                           std::vector<RealizationRecord> records) {
  return {kVersion,     kGitCommit,      scene.path,
          scene.text,   scene.overrides, resolved_scene_text(scene),
          realizations, variants,        std::move(records)};
}

void write_checkpoint(const fs::path& dir, const Checkpoint& checkpoint) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  const fs::path file = checkpoint_path(dir);
  const fs::path temporary = file.string() + ".partial-" + std::to_string(::getpid());
  const std::string bytes = to_bytes(checkpoint);
  const int fd = open_new_file(temporary);
  const bool written = fd >= 0 && write_fully(fd, bytes) && ::fsync(fd) == 0;
  const bool closed = fd >= 0 && ::close(fd) == 0;
  if (!written || !closed || ::rename(temporary.c_str(), file.c_str()) != 0) {
    const std::string reason = std::strerror(errno);
    fs::remove(temporary, ec);
    throw RunError("cannot write the checkpoint " + file.string() + ": " + reason);
  }
  try_sync_directory(dir);
}

Checkpoint read_checkpoint(const fs::path& dir) {
  const fs::path file = checkpoint_path(dir);
  if (!fs::is_regular_file(file))
    throw InputError("--resume", to_text(dir.string()),
                     "a run's output directory holding a checkpoint (" + file.string() + " does not exist)");
  Checkpoint c;
  try {
    c = from_bytes(read_all(file), file);
  } catch (const RunError& e) {  // a count running past the end
    throw damaged(file, e.what());
  }
  const std::string theirs = "shockgas " + c.version + " (commit " + c.commit + ")",
                    ours = std::string("shockgas ") + kVersion + " (commit " + kGitCommit + ")";
  if (theirs != ours)
    throw InputError(
        "--resume", to_text(dir.string()),
        "a checkpoint of this build, " + ours + " (it was written by " + theirs + "; it is left as it is)");
  return c;
}

std::string checkpoint_scene_name(const Checkpoint& checkpoint) { return scene_name_of(checkpoint.resolved); }

void remove_checkpoint(const fs::path& dir) {
  std::error_code ec;
  fs::remove(checkpoint_path(dir), ec);
  remove_run_states(dir);
}

}  // namespace shockgas::app
