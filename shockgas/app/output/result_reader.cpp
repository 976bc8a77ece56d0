#include "shockgas/app/output/result_reader.hpp"

#include <algorithm>
#include <cstring>

#include "shockgas/app/files/byte_buffer.hpp"
#include "shockgas/app/files/durable_file.hpp"
#include "shockgas/app/files/file_problem.hpp"
#include "shockgas/app/files/isolated_call.hpp"
#include "shockgas/app/files/manifest.hpp"
#include "shockgas/app/output/statistics_files.hpp"
#include "shockgas/app/scene/scene.hpp"
#include "shockgas/core/error.hpp"
#include "shockgas/core/memory_limit.hpp"

namespace shockgas::app {

namespace fs = std::filesystem;

namespace {

// The stream of a reading: frames of a tag, the payload's length (u64) and the
// payload (byte_buffer.hpp), in this order: every dataset ('D'), every group
// ('G') with its attributes ('A'), the values asked for ('V'), then the end
// ('Z'), or a problem ('E') where the library refused the file.
enum Tag : char { kDataset = 'D', kGroup = 'G', kAttribute = 'A', kValues = 'V', kProblem = 'E', kEnd = 'Z' };

void frame(const Send& send, Tag tag, const ByteWriter& payload) {
  const std::uint64_t size = payload.bytes().size();
  send(reinterpret_cast<const char*>(&tag), 1);
  send(reinterpret_cast<const char*>(&size), sizeof size);
  send(payload.bytes().data(), payload.bytes().size());
}

// What the library reads of the file, as frames (in the reading process):
// `part` sends its frames, then the end; or the problem where the library
// refused the file.
void read_frames(const std::string& path, Verification checked,
                 const std::function<void(const Hdf5File&, const Send&)>& part, const Send& send) {
  try {
    const Hdf5File file = Hdf5File::open(path, checked);
    part(file, send);
    frame(send, kEnd, ByteWriter());
  } catch (const FileProblem& e) {
    ByteWriter p;
    p.text(e.problem()), p.text(e.detail());
    frame(send, kProblem, p);
  } catch (const std::exception& e) {
    ByteWriter p;
    p.text("damaged"), p.text(std::string("the HDF5 library cannot read it: ") + e.what());
    frame(send, kProblem, p);
  }
}

// The file's layout: every dataset, every group with its attributes.
void send_layout(const Hdf5File& file, const Send& send) {
  for (const DatasetInfo& d : file.datasets()) {
    ByteWriter w;
    w.text(d.path), w.text(d.type), w.text(d.unit), w.text(d.description), w.u64(d.shape.size());
    for (const auto n : d.shape) w.u64(n);
    frame(send, kDataset, w);
  }
  for (const std::string& group : file.groups()) {
    ByteWriter g;
    g.text(group);
    frame(send, kGroup, g);
    for (const auto& [name, value] : file.attributes(group)) {
      ByteWriter a;
      a.text(group), a.text(name), a.text(value);
      frame(send, kAttribute, a);
    }
  }
}

// The values of the datasets `paths`, one after the other.
void send_values(const Hdf5File& file, const std::vector<std::string>& paths, const Send& send) {
  for (const std::string& path : paths) {
    ByteWriter v;
    v.text(path), v.numbers(file.read(path));
    frame(send, kValues, v);
  }
}

// Rebuilds the contents from the frames as they arrive.
class FrameReader {
 public:
  explicit FrameReader(ResultContents& out) : out_(out) {}
  void add(const char* data, std::size_t size) {
    buffer_.append(data, size);
    std::size_t at = 0;
    while (!ended() && buffer_.size() - at >= 9) {
      std::uint64_t length;
      std::memcpy(&length, buffer_.data() + at + 1, sizeof length);
      if (length > buffer_.size() - at - 9) break;
      take(static_cast<Tag>(buffer_[at]), buffer_.substr(at + 9, length));
      at += 9 + length;
    }
    buffer_.erase(0, at);
  }
  bool ended() const { return end_ || !problem_.empty(); }
  const std::string& problem() const { return problem_; }
  const std::string& detail() const { return detail_; }

 private:
  void take(Tag tag, const std::string& payload) {
    ByteReader in(payload, "the reading of " + out_.path);
    if (tag == kDataset) {
      DatasetInfo d{in.text(), {}, in.text(), in.text(), in.text()};
      d.shape.resize(in.u64());
      for (auto& n : d.shape) n = in.u64();
      out_.datasets.push_back(std::move(d));
    } else if (tag == kGroup) {
      out_.groups.push_back(in.text());
    } else if (tag == kAttribute) {
      const std::string group = in.text(), name = in.text();
      out_.attributes[group].emplace_back(name, in.text());
    } else if (tag == kValues) {
      const std::string path = in.text();
      out_.values[path] = in.numbers();
    } else if (tag == kProblem) {
      problem_ = in.text(), detail_ = in.text();
    } else if (tag == kEnd) {
      end_ = true;
    }
  }
  ResultContents& out_;
  std::string buffer_, problem_, detail_;
  bool end_ = false;
};

// A file checked against its manifest holds the scene the manifest names (a
// manifest of another run's files would otherwise vouch for this one); a
// statistics file also where the manifest names that scene's statistics run
// (`shockgas stats`: "<scene>-stats").
void require_manifest_scene(const ResultContents& out) {
  const fs::path dir = fs::path(out.path).parent_path();
  const auto manifest = read_manifest(dir.empty() ? "." : dir);
  const std::string resolved = out.attribute("/", "resolved_parameters");
  const std::string held = resolved.empty() ? "" : scene_name_of(resolved);
  const bool statistics = std::find(out.groups.begin(), out.groups.end(), "/statistics") != out.groups.end();
  if (manifest && !held.empty() && held != manifest->scene &&
      !(statistics && statistics_run_name(held) == manifest->scene))
    throw result_problem(
        out.path, "not as its manifest.json records",
        "manifest.json names the scene " + to_text(manifest->scene) + ", the file holds " + to_text(held));
}

}  // namespace

const std::vector<std::pair<std::string, std::string>>& ResultContents::attributes_of(
    const std::string& group) const {
  static const std::vector<std::pair<std::string, std::string>> none;
  const auto it = attributes.find(group);
  return it == attributes.end() ? none : it->second;
}

std::string ResultContents::attribute(const std::string& group, const std::string& name) const {
  for (const auto& [n, value] : attributes_of(group))
    if (n == name) return value;
  return "";
}

bool reads_in_process(Verification) { return false; }

ResultContents read_result(const fs::path& file, const ValueFilter& values) {
  const fs::path path = result_file_of(file);
  return read_result(path, check_result_file(path), values);
}

namespace {

// Why the library may have failed inside a file that passed check_result_file().
std::string damage_note(Verification checked) {
  switch (checked) {
    case Verification::manifest:
      return "though it is as manifest.json records: that manifest was written for the damaged file";
    case Verification::own_checksum:
      return "though it is as its own checksum records: it was written damaged, or its checksum written "
             "again";
    case Verification::damaged:
      return "";  // its checksum said so already
    case Verification::no_manifest:
      break;
  }
  return "and it has no manifest.json to check it against";
}

// zlib's deflate stores at most 1032 bytes in 1 (its limit: a run of 258 equal
// bytes in 2 bits); a file of layout 1.0 stores its values uncompressed.
constexpr double kMostDeflated = 1032;
// Copies of the values asked for, as float64, that are held at once: in the
// reading process the library's read and its frame (byte_buffer.hpp); here
// the frame as it arrives, its payload and the values kept (FrameReader).
constexpr double kReaderCopies = 2, kKeptCopies = 3;

// The reading process's room besides the values: the HDF5 library and its
// caches (512 MiB), and three times the file's bytes for the metadata it reads.
double library_room(double file_bytes) { return 3 * file_bytes + 512.0 * (1 << 20); }

// The values of a dataset as float64, as its metadata declare them [bytes].
double declared_bytes(const DatasetInfo& d) {
  double values = 1;
  for (const auto n : d.shape) values *= static_cast<double>(n);
  return 8 * values;
}

// More values than the file's bytes can hold, deflated as much as deflate can:
// a damaged count, refused before the library allocates them.
void require_room(const std::string& path, const DatasetInfo& d, double file_bytes) {
  if (declared_bytes(d) > kMostDeflated * file_bytes + 1e6)
    throw result_problem(path, "damaged",
                         "dataset " + d.path + " declares " + to_text(declared_bytes(d) / 8, 3) +
                             " values, more than its " + size_text(file_bytes) + " can hold deflated (" +
                             to_text(kMostDeflated) + " to 1 at most)");
}

// Values whose copies cannot fit in the memory this process may use: refused
// before they are read.
void require_memory_for(const std::string& path, double declared) {
  const MemoryLimit limit = memory_limit();
  const double need = (kReaderCopies + kKeptCopies) * declared;
  if (need <= limit.bytes) return;
  throw result_problem(path, "too large to read",
                       "its datasets declare " + size_text(declared) +
                           " of values (as float64); reading them takes about " + size_text(need) + ", " +
                           size_text(limit.bytes) + " available (" + limit.source + ")");
}

// How long the reading process may send nothing before it is taken as hung
// [s]: the HDF5 library can loop without end inside a damaged file (a zeroed
// global heap under a string attribute did), and reading a sound one, its
// chunks inflated and checksummed, runs at hundreds of MB/s: 10 s, and a
// second more for every 10 MB of `bytes` it may have to read.
double silence_allowed(double bytes) { return 10 + bytes / 1e7; }

// Reads one part of the file into `out`, in a reading process that may use
// `memory` bytes more than this one holds at the fork and read about `bytes`:
// FileProblem where the library refused the file or failed inside it.
void read_part(ResultContents& out, Verification checked, double memory, double bytes,
               const std::function<void(const Hdf5File&, const Send&)>& part) {
  FrameReader frames(out);
  const auto read = [&](const Send& send) { read_frames(out.path, checked, part, send); };
  const auto receive = [&](const char* data, std::size_t size) { frames.add(data, size); };
  std::string ended;
  if (reads_in_process(checked))
    read(receive);
  else
    ended = run_isolated(read, receive, static_cast<std::uint64_t>(std::min(memory, 1e18)),
                         silence_allowed(bytes), &hdf5_calls());
  if (!frames.problem().empty()) throw result_problem(out.path, frames.problem(), frames.detail());
  if (frames.ended() && ended.empty()) return;
  const std::string note = damage_note(checked);
  throw result_problem(out.path, "damaged",
                       "the HDF5 library failed inside it (" +
                           (ended.empty() ? std::string("no answer") : ended) + ")" +
                           (note.empty() ? "" : ", " + note));
}

// The layout first (with every_chunk, every chunk read block by block), in a
// reading process sized by the file's bytes; then the values asked for, in one
// sized by their declared (uncompressed) size: deflate lets a file hold 1000
// times its bytes of values.
ResultContents read_contents(const fs::path& file, Verification checked, const ValueFilter& values,
                             bool every_chunk) {
  ResultContents out;
  out.path = file.string();
  out.verification = checked;
  std::error_code ec;
  const std::uintmax_t size = fs::file_size(file, ec);
  const double file_bytes = ec ? 0 : static_cast<double>(size);
  read_part(out, checked, library_room(file_bytes), file_bytes,
            [every_chunk](const Hdf5File& h5, const Send& send) {
              if (every_chunk) h5.check_every_chunk();
              send_layout(h5, send);
            });
  std::vector<std::string> asked;
  double declared = 0;
  for (const DatasetInfo& d : out.datasets) {
    if (!values || !values(d.path)) continue;
    require_room(out.path, d, file_bytes);
    asked.push_back(d.path);
    declared += declared_bytes(d);
  }
  if (!asked.empty()) {
    require_memory_for(out.path, declared);
    read_part(out, checked, library_room(file_bytes) + kReaderCopies * declared, file_bytes + declared,
              [&asked](const Hdf5File& h5, const Send& send) { send_values(h5, asked, send); });
  }
  if (out.verified()) require_manifest_scene(out);
  return out;
}

}  // namespace

ResultContents read_result(const fs::path& file, Verification checked, const ValueFilter& values) {
  return read_contents(file, checked, values, false);
}

ResultContents written_contents(const Hdf5File& writing, const ValueFilter& values) {
  ResultContents out;
  out.path = writing.path();
  out.verification = writing.verification();
  FrameReader frames(out);
  const Send receive = [&](const char* data, std::size_t size) { frames.add(data, size); };
  send_layout(writing, receive);
  std::vector<std::string> asked;
  for (const DatasetInfo& d : out.datasets)
    if (values && values(d.path)) asked.push_back(d.path);
  send_values(writing, asked, receive);
  return out;
}

ResultContents read_every_chunk(const fs::path& file, Verification checked) {
  return read_contents(file, checked, {}, true);
}

}  // namespace shockgas::app
