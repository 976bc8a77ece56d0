#include "shockgas/app/records/state_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <bit>
#include <cerrno>
#include <cstring>
#include <optional>
#include <utility>

#include "shockgas/app/files/durable_file.hpp"
#include "shockgas/app/files/stream_hash.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::app {

namespace fs = std::filesystem;

namespace {

constexpr std::size_t kChunk = 4096;  // bodies per read: 96 KiB for the three columns
constexpr std::size_t kEntryWords = 7, kEntryBytes = kEntryWords * 8, kTrailerBytes = std::size_t{3} * 8;

std::string reason() { return std::strerror(errno); }

// An index entry as its words (the file's index and saved()), and back.
void append_words(const StateFileEntry& e, std::vector<std::uint64_t>& words) {
  words.insert(words.end(),
               {e.k, std::bit_cast<std::uint64_t>(e.t), e.n, e.offset, e.sums[0], e.sums[1], e.sums[2]});
}
StateFileEntry entry_of(const std::uint64_t* w) {
  return {w[0], std::bit_cast<double>(w[1]), w[2], w[3], {w[4], w[5], w[6]}};
}

// The state an index entry names, as messages name it.
std::string state_name(std::uint64_t k) {
  if (k == kFinalState) return "the final state";
  if (k == kHeaviestCluster) return "the heaviest cluster";
  return "snapshot " + std::to_string(k);
}

// What StateFileWriter::saved() said: the bytes written and the index so far;
// nullopt for bytes it cannot have written.
struct Save {
  std::uint64_t end = 0;
  std::vector<StateFileEntry> index;
};
std::optional<Save> parse_save(const std::string& saved) {
  std::vector<std::uint64_t> words(saved.size() / 8);
  std::memcpy(words.data(), saved.data(), words.size() * 8);
  if (words.size() < 2 || saved.size() % 8 != 0 || words[1] > words.size() ||
      words.size() != 2 + words[1] * kEntryWords)
    return std::nullopt;
  Save save{words[0], {}};
  for (std::size_t e = 0; e < words[1]; ++e) save.index.push_back(entry_of(&words[2 + kEntryWords * e]));
  return save;
}

}  // namespace

fs::path state_file_path(const fs::path& dir, std::uint64_t ensemble) {
  return dir / ("states-" + std::to_string(ensemble) + ".bin");
}

fs::path states_in_progress_path(const fs::path& dir, std::uint64_t ensemble) {
  return state_file_path(dir, ensemble).string() + ".tmp";
}

fs::path find_state_file(const std::vector<fs::path>& dirs, std::uint64_t ensemble) {
  std::error_code ec;
  for (const fs::path& dir : dirs)
    if (!dir.empty() && fs::exists(state_file_path(dir, ensemble), ec)) return state_file_path(dir, ensemble);
  return state_file_path(dirs.empty() ? fs::path() : dirs.back(), ensemble);
}

void move_state_file(const fs::path& from, const fs::path& to, std::uint64_t ensemble) {
  std::error_code ec;
  if (from.empty() || from == to || !fs::exists(state_file_path(from, ensemble), ec)) return;
  fs::create_directories(to, ec);
  fs::rename(state_file_path(from, ensemble), state_file_path(to, ensemble), ec);
  if (ec) throw RunError(write_failure(state_file_path(to, ensemble), ec.message()));
}

bool is_state_file(const fs::path& name) {
  std::string s = name.string();
  if (s.size() > 4 && s.compare(s.size() - 4, 4, ".tmp") == 0) s.resize(s.size() - 4);
  if (s.rfind("states-", 0) != 0 || s.size() <= 11 || s.compare(s.size() - 4, 4, ".bin") != 0) return false;
  const std::string number = s.substr(7, s.size() - 11);
  return std::all_of(number.begin(), number.end(), [](char c) { return c >= '0' && c <= '9'; });
}

void remove_state_files(const fs::path& dir) {
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dir, ec))
    if (is_state_file(entry.path().filename())) fs::remove(entry.path(), ec);
}

// ---- Writing ----

StateFileWriter::StateFileWriter(fs::path path, FinalStateUse use)
    : path_(std::move(path)),
      temporary_(path_.string() + ".tmp"),
      use_(std::move(use)) {  // states_in_progress_path
  fd_ = open_new_file(temporary_);
  if (fd_ < 0) throw RunError(write_failure(temporary_, reason()));
  connect_sink();
}

StateFileWriter::StateFileWriter(fs::path path, const std::string& saved, FinalStateUse use)
    : path_(std::move(path)), temporary_(path_.string() + ".tmp"), use_(std::move(use)), kept_(true) {
  const auto bad = [&](const std::string& why) {
    return InputError("--resume", to_text(temporary_.string()),
                      "the states file of the saved run, as it was at the save (" + why + ")");
  };
  std::optional<Save> save = parse_save(saved);
  if (!save) throw bad("a malformed save");
  end_ = save->end;
  index_ = std::move(save->index);
  fd_ = ::open(temporary_.c_str(), O_WRONLY | O_NOFOLLOW | O_CLOEXEC);
  if (fd_ < 0) throw bad(reason());
  struct stat st {};
  if (::fstat(fd_, &st) != 0 || static_cast<std::uint64_t>(st.st_size) < end_ ||
      ::ftruncate(fd_, static_cast<off_t>(end_)) != 0) {
    ::close(std::exchange(fd_, -1));
    throw bad("shorter than the save says, or not writable");
  }
  connect_sink();
}

void StateFileWriter::connect_sink() {
  sink_.snapshot = [this](std::size_t k, double t, const particles::StateReader& s) { append(k, t, s); };
  sink_.final_state = [this](double t, const particles::StateReader& s) { append_final(t, s); };
}

StateFileWriter::~StateFileWriter() {
  if (fd_ < 0) return;  // committed
  ::close(fd_);
  std::error_code ec;
  if (!kept_) fs::remove(temporary_, ec);
}

std::string StateFileWriter::saved() {
  if (::fsync(fd_) != 0) throw RunError(write_failure(temporary_, reason()));
  kept_ = true;
  std::vector<std::uint64_t> words{end_, index_.size()};
  for (const StateFileEntry& e : index_) append_words(e, words);
  return std::string(reinterpret_cast<const char*>(words.data()), words.size() * 8);
}

void StateFileWriter::move_to(const fs::path& dir) {
  if (temporary_.parent_path() == dir) return;
  std::error_code ec;
  fs::create_directories(dir, ec);
  const fs::path moved = dir / temporary_.filename();
  fs::rename(temporary_, moved, ec);
  if (ec) throw RunError(write_failure(moved, ec.message()));
  temporary_ = moved;
  path_ = dir / path_.filename();
}

void StateFileWriter::write_at(std::uint64_t offset, const void* data, std::size_t bytes) {
  const char* p = static_cast<const char*>(data);
  while (bytes > 0) {
    const ssize_t n = ::pwrite(fd_, p, bytes, static_cast<off_t>(offset));
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw RunError(write_failure(temporary_, reason()));
    p += n, offset += static_cast<std::uint64_t>(n), bytes -= static_cast<std::size_t>(n);
  }
}

// x, v and m each in their own stretch of the file, filled chunk by chunk.
void StateFileWriter::append(std::uint64_t k, double t, const particles::StateReader& state) {
  const std::uint64_t n = state.size(), base = end_;
  std::uint64_t at = 0;
  StreamHash sum[3];
  state.read([&](const double* x, const double* v, const double* m, std::size_t count) {
    if (at + count > n) throw RunError("state of " + std::to_string(n) + " bodies read with more");
    const std::size_t bytes = count * sizeof(double);
    int c = 0;
    for (const double* column : {x, v, m}) {
      write_at(base + (c * n + at) * 8, column, bytes);
      sum[c++].add(reinterpret_cast<const char*>(column), bytes);
    }
    at += count;
  });
  if (at != n) throw RunError("state of " + std::to_string(n) + " bodies read with " + std::to_string(at));
  end_ = base + 3 * n * 8;
  index_.push_back({k, t, n, base, {sum[0].value(), sum[1].value(), sum[2].value()}});
}

void StateFileWriter::append_final(double t, const particles::StateReader& state) {
  if (use_.heaviest)
    if (const std::optional<HeaviestCluster> h = use_.heaviest(t, state)) {
      const Bodies one{{h->x}, {h->v}, {h->m}};
      append(kHeaviestCluster, t, particles::BodiesReader(one));
    }
  if (!use_.keep || use_.keep(state.size())) append(kFinalState, t, state);
}

void StateFileWriter::commit() {
  std::vector<std::uint64_t> tail;
  for (const StateFileEntry& e : index_) append_words(e, tail);
  tail.insert(tail.end(), {index_.size(), end_, kStateFileMagic});
  write_at(end_, tail.data(), tail.size() * sizeof(std::uint64_t));
  if (::close(std::exchange(fd_, -1)) != 0) {
    fs::remove(temporary_);
    throw RunError(write_failure(temporary_, reason()));
  }
  std::error_code ec;
  fs::rename(temporary_, path_, ec);
  if (ec) {
    fs::remove(temporary_, ec);
    throw RunError(write_failure(path_, ec.message()));
  }
}

void sync_state_file(const fs::path& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw RunError(write_failure(path, reason()));
  const bool synced = ::fsync(fd) == 0 || errno == EINVAL;
  const std::string why = synced ? "" : reason();
  ::close(fd);
  if (!synced) throw RunError(write_failure(path, why));
}

// ---- Reading ----

void StoredStates::read_at(std::uint64_t offset, void* data, std::size_t bytes) const {
  char* p = static_cast<char*>(data);
  while (bytes > 0) {
    const ssize_t n = ::pread(fd_, p, bytes, static_cast<off_t>(offset));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) throw RunError("cannot read " + path_.string() + ": " + (n < 0 ? reason() : "it ends early"));
    p += n, offset += static_cast<std::uint64_t>(n), bytes -= static_cast<std::size_t>(n);
  }
}

void StoredStates::State::check(int c, std::uint64_t read) const {
  static const char* const column[] = {"x", "v", "m"};
  if (read != sums_[static_cast<std::size_t>(c)])
    throw RunError("state file " + file_->path_.string() + " is damaged: " + column[c] + " of " + name_ +
                   " does not match its checksum");
}

// The chunks reach the caller before the last is checked: a damaged file ends
// the run with a RunError (its outputs are staged, and discarded).
void StoredStates::State::read(const Chunk& chunk) const {
  std::vector<double> x(kChunk), v(kChunk), m(kChunk);
  StreamHash sum[3];
  for (std::uint64_t at = 0; at < n_; at += kChunk) {
    const std::size_t count = static_cast<std::size_t>(std::min<std::uint64_t>(kChunk, n_ - at));
    int c = 0;
    for (double* column : {x.data(), v.data(), m.data()}) {
      file_->read_at(offset_ + (c * n_ + at) * 8, column, count * 8);
      sum[c++].add(reinterpret_cast<const char*>(column), count * 8);
    }
    chunk(x.data(), v.data(), m.data(), count);
  }
  for (int c = 0; c < 3; ++c) check(c, sum[c].value());
}

void StoredStates::State::read_column(int c,
                                      const std::function<void(const double*, std::size_t)>& piece) const {
  std::vector<double> buffer(3 * kChunk);
  StreamHash sum;
  for (std::uint64_t at = 0; at < n_; at += buffer.size()) {
    const std::size_t count = static_cast<std::size_t>(std::min<std::uint64_t>(buffer.size(), n_ - at));
    file_->read_at(offset_ + (static_cast<std::uint64_t>(c) * n_ + at) * 8, buffer.data(), count * 8);
    sum.add(reinterpret_cast<const char*>(buffer.data()), count * 8);
    piece(buffer.data(), count);
  }
  check(c, sum.value());
}

std::shared_ptr<const StoredStates> StoredStates::open(const fs::path& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw RunError("cannot read " + path.string() + ": " + reason());
  std::shared_ptr<StoredStates> s(new StoredStates(path, fd));
  auto damaged = [&](const std::string& what) {
    return RunError("state file " + path.string() + " is damaged: " + what);
  };
  struct stat st {};
  if (::fstat(fd, &st) != 0) throw RunError("cannot read " + path.string() + ": " + reason());
  const auto size = static_cast<std::uint64_t>(st.st_size);
  if (size < kTrailerBytes) throw damaged("shorter than its trailer");
  std::uint64_t trailer[3];
  s->read_at(size - kTrailerBytes, trailer, sizeof trailer);
  const auto [count, index, magic] = trailer;
  if (magic != kStateFileMagic) throw damaged("no state file's mark at its end");
  if (index > size || (size - kTrailerBytes - index) / kEntryBytes != count ||
      (size - kTrailerBytes - index) % kEntryBytes != 0)
    throw damaged("its index does not fit its size");
  std::vector<std::uint64_t> entries(kEntryWords * count);
  if (count > 0) s->read_at(index, entries.data(), entries.size() * 8);
  for (std::uint64_t i = 0; i < count; ++i) {
    const StateFileEntry e = entry_of(&entries[kEntryWords * i]);
    if (e.offset > index || e.n > (index - e.offset) / 24) throw damaged("a state beyond its data");
    if (e.k == kFinalState)
      s->final_.push_back(State(s.get(), state_name(e.k), e));
    else if (e.k == kHeaviestCluster && e.n == 1)
      s->heaviest_.push_back(State(s.get(), state_name(e.k), e));
    else if (e.k == s->snapshots_.size())
      s->snapshots_.push_back(State(s.get(), state_name(e.k), e));
    else
      throw damaged("snapshot " + std::to_string(e.k) + " out of order");
  }
  if (s->final_.size() > 1 || s->heaviest_.size() > 1) throw damaged("two final states");
  if (s->final_.empty() && s->heaviest_.empty()) throw damaged("no final state");
  return s;
}

std::optional<std::string> StoredStates::problem(const fs::path& path) noexcept {
  try {
    const auto file = open(path);
    const auto read_all = [](const State& state) {
      for (int c = 0; c < 3; ++c) state.read_column(c, [](const double*, std::size_t) {});
    };
    for (const State& state : file->snapshots_) read_all(state);
    for (const State& state : file->final_) read_all(state);
    for (const State& state : file->heaviest_) read_all(state);
    return std::nullopt;
  } catch (const std::exception& e) {
    return std::string(e.what());
  } catch (...) {
    return "unreadable";
  }
}

std::optional<std::string> StoredStates::saved_problem(const fs::path& temporary,
                                                       const std::string& saved) noexcept {
  try {
    const std::optional<Save> save = parse_save(saved);
    if (!save) return "its save is malformed";
    const int fd = ::open(temporary.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return "cannot read " + temporary.string() + ": " + reason();
    const std::shared_ptr<StoredStates> file(new StoredStates(temporary, fd));
    struct stat st {};
    if (::fstat(fd, &st) != 0 || static_cast<std::uint64_t>(st.st_size) < save->end)
      return "state file " + temporary.string() + " is shorter than its save says";
    for (const StateFileEntry& e : save->index) {
      if (e.offset > save->end || e.n > (save->end - e.offset) / 24)
        return "state file " + temporary.string() + " is damaged: its save lists a state beyond its data";
      const State state(file.get(), state_name(e.k), e);
      for (int c = 0; c < 3; ++c) state.read_column(c, [](const double*, std::size_t) {});
    }
    return std::nullopt;
  } catch (const std::exception& e) {
    return std::string(e.what());
  } catch (...) {
    return "unreadable";
  }
}

std::optional<HeaviestCluster> StoredStates::heaviest_cluster() const {
  if (heaviest_.empty()) return std::nullopt;
  HeaviestCluster h;
  heaviest_[0].read([&](const double* x, const double* v, const double* m, std::size_t) {
    h = {x[0], v[0], m[0]};
  });
  return h;
}

StoredStates::~StoredStates() { ::close(fd_); }

bool keeps_states_apart(const Scene& scene) {
  return !(scene.has_continuum && scene.has_compare) && !scene.output.animation;
}

}  // namespace shockgas::app
