#include "shockgas/app/output/result_reader.hpp"

#include <cstring>

#include "shockgas/app/files/byte_buffer.hpp"
#include "shockgas/app/files/file_problem.hpp"
#include "shockgas/app/files/isolated_call.hpp"
#include "shockgas/app/files/manifest.hpp"
#include "shockgas/app/scene/scene.hpp"
#include "shockgas/core/error.hpp"

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

// zlib's deflate stores at most 1032 bytes in 1 (its limit: a run of 258 equal
// bytes in 2 bits); a file of layout 1.0 stores its values uncompressed.
constexpr double kMostDeflated = 1032;

// More values than the file's bytes can hold, deflated as much as deflate can:
// a damaged count, refused before the library allocates them.
void require_room(const DatasetInfo& d, std::uint64_t file_bytes) {
  double values = 1;
  for (const auto n : d.shape) values *= static_cast<double>(n);
  if (values * 8 > kMostDeflated * static_cast<double>(file_bytes) + 1e6)
    throw RunError("dataset " + d.path + " claims " + to_text(values, 3) +
                   " values, more than the file holds");
}

// What the library reads of the file, as frames (in the child process).
// With every_chunk, every chunk is read first (check_every_chunk).
void read_frames(const std::string& path, Verification checked, const ValueFilter& values, bool every_chunk,
                 const Send& send) {
  try {
    const Hdf5File file = Hdf5File::open(path, checked);
    if (every_chunk) file.check_every_chunk();
    const std::uint64_t bytes = fs::file_size(path);
    const std::vector<DatasetInfo> datasets = file.datasets();
    for (const DatasetInfo& d : datasets) {
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
    for (const DatasetInfo& d : datasets) {
      if (!values || !values(d.path)) continue;
      require_room(d, bytes);
      ByteWriter v;
      v.text(d.path), v.numbers(file.read(d.path));
      frame(send, kValues, v);
    }
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
// manifest of another run's files would otherwise vouch for this one).
void require_manifest_scene(const ResultContents& out) {
  const fs::path dir = fs::path(out.path).parent_path();
  const auto manifest = read_manifest(dir.empty() ? "." : dir);
  const std::string resolved = out.attribute("/", "resolved_parameters");
  const std::string held = resolved.empty() ? "" : scene_name_of(resolved);
  if (manifest && !held.empty() && held != manifest->scene)
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
    case Verification::no_manifest:
      break;
  }
  return "and it has no manifest.json to check it against";
}

ResultContents read_contents(const fs::path& file, Verification checked, const ValueFilter& values,
                             bool every_chunk) {
  ResultContents out;
  out.path = file.string();
  out.verification = checked;
  FrameReader frames(out);
  const auto read = [&](const Send& send) { read_frames(out.path, checked, values, every_chunk, send); };
  const auto receive = [&](const char* data, std::size_t size) { frames.add(data, size); };
  std::string ended;
  if (reads_in_process(checked)) {
    read(receive);
  } else {
    std::error_code ec;
    const auto bytes = static_cast<std::uint64_t>(fs::file_size(file, ec));
    ended = run_isolated(read, receive, 3 * bytes + (512u << 20), &hdf5_calls());
  }
  if (!frames.problem().empty()) throw result_problem(out.path, frames.problem(), frames.detail());
  if (frames.ended() && ended.empty()) {
    if (out.verified()) require_manifest_scene(out);
    return out;
  }
  throw result_problem(out.path, "damaged",
                       "the HDF5 library failed inside it (" +
                           (ended.empty() ? std::string("no answer") : ended) + "), " + damage_note(checked));
}

}  // namespace

ResultContents read_result(const fs::path& file, Verification checked, const ValueFilter& values) {
  return read_contents(file, checked, values, false);
}

ResultContents read_every_chunk(const fs::path& file, Verification checked) {
  return read_contents(file, checked, {}, true);
}

}  // namespace shockgas::app
