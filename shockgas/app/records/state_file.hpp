#pragma once
// Realization 0's states (its snapshots and final state) kept on disk while the
// rest of the ensemble runs, instead of whole in its record: a StateSink writes
// each state in chunks as the engine reaches it, and the writers of result.h5
// and summary.json read it back in chunks. The process holds a few chunks of
// it, never a whole state (docs/performance.md, "Memory of the command").
//
// The file, states-<ensemble>.bin, is written in the run's work directory
// (run_directory.hpp) and moved beside the run's checkpoint (checkpoint.hpp:
// DIR/states-<ensemble>.bin) when a checkpoint refers to it, so that a
// resumed run finds the states of a realization 0 saved before the
// interruption; written under a temporary name and renamed when complete: a
// kill leaves the temporary one (in the work directory, which the next run
// removes; beside a checkpoint, which its next save or the finished run's
// result replaces) or a whole file. It is put on the disk
// (fsync) only when a checkpoint that holds its record is saved
// (checkpointer.hpp): a run that ends without one does not wait for it.
// Its contents, numbers in the machine's byte order:
//   per state, in the order reached: x[n], v[n], m[n] (float64),
//   the index: per state its snapshot number (kFinalState for the final state,
//   kHeaviestCluster for its heaviest cluster, one body: x = centre of mass),
//   t (float64), n and the offset of its x (u64), and a checksum of each of
//   its three columns (StreamHash of their bytes, u64),
//   the state count (u64), the offset of the index (u64), kStateFileMagic.
// A read checks the columns it reads against their checksums (RunError naming
// the file); a resumed run checks the whole file first and runs realization 0
// again when it is damaged.
#include <array>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "shockgas/app/records/final_cluster.hpp"
#include "shockgas/app/scene/scene.hpp"
#include "shockgas/particles/state_sink.hpp"

namespace shockgas::app {

inline constexpr std::uint64_t kStateFileMagic = 0x3273657461747367;  // "gstates2"
inline constexpr std::uint64_t kFinalState = ~std::uint64_t{0};       // the index's k of the final state
inline constexpr std::uint64_t kHeaviestCluster = kFinalState - 1;    // ... and of its heaviest cluster

// One state's entry in the index (7 words: k, t, n, offset, the three sums).
struct StateFileEntry {
  std::uint64_t k;  // snapshot number, or kFinalState
  double t;
  std::uint64_t n, offset;            // bodies, and the offset of its x
  std::array<std::uint64_t, 3> sums;  // StreamHash of x, v and m
};

// Whether realization 0 of this scene can keep its states in a state file: not
// when the comparison needs its final state whole, nor an animation its
// snapshots (frames.hpp).
bool keeps_states_apart(const Scene& scene);

// DIR/states-<ensemble>.bin
std::filesystem::path state_file_path(const std::filesystem::path& dir, std::uint64_t ensemble);
// DIR/states-<ensemble>.bin.tmp: the file while it is written (StateFileWriter).
std::filesystem::path states_in_progress_path(const std::filesystem::path& dir, std::uint64_t ensemble);
// The states file of `ensemble` in the first of dirs that holds it (a run's
// work directory, then its checkpoint's); the path in the last if none does.
std::filesystem::path find_state_file(const std::vector<std::filesystem::path>& dirs, std::uint64_t ensemble);
// Moves the committed states file of `ensemble` from `from` into `to` (created
// if missing), if it is in from; RunError if it cannot.
void move_state_file(const std::filesystem::path& from, const std::filesystem::path& to,
                     std::uint64_t ensemble);
// Whether a file name is a state file's, or what a killed run left of one
// (states-<ensemble>.bin, states-<ensemble>.bin.tmp).
bool is_state_file(const std::filesystem::path& name);
// Removes the state files of dir.
void remove_state_files(const std::filesystem::path& dir);
// fsync of a committed state file; RunError naming it if that fails.
void sync_state_file(const std::filesystem::path& path);

// What a StateFileWriter keeps of the final state it is handed: the state
// whole when keep(n) says so for its n bodies (always, without keep), and its
// heaviest cluster, heaviest(t, state), either way (none, without heaviest).
// A final state that result.h5 does not keep then never reaches the disk.
struct FinalStateUse {
  std::function<bool(std::size_t bodies)> keep;
  std::function<std::optional<HeaviestCluster>(double t, const particles::StateReader& state)> heaviest;
};

// Writes the states handed to sink() into the file under a temporary name;
// commit() makes it the file. Without commit() the destructor removes it.
// RunError naming the file and the system's reason when a write fails.
class StateFileWriter {
 public:
  explicit StateFileWriter(std::filesystem::path path, FinalStateUse use = {});
  // Goes on with the temporary file of a run saved while it ran
  // (run_state_file.hpp): the states `saved` (what saved() returned then)
  // lists are kept, anything written after them dropped. InputError (key
  // "--resume") naming the file when it is missing or shorter than they say.
  StateFileWriter(std::filesystem::path path, const std::string& saved, FinalStateUse use = {});
  ~StateFileWriter();
  StateFileWriter(const StateFileWriter&) = delete;
  StateFileWriter& operator=(const StateFileWriter&) = delete;

  // Receives the snapshots and the final state of one run (the calls come one
  // at a time, in the order the states are reached).
  const particles::StateSink& sink() const { return sink_; }
  // The index written, the file under its own name (not yet synced).
  void commit();
  // For a save of the run that writes here: the states written so far, synced
  // (the save refers to them), as bytes for the constructor above; from now on
  // the temporary file outlives this writer (a resumed run goes on with it).
  std::string saved();
  // Moves the file being written into dir (created if missing; the same file
  // system), where a checkpoint refers to it; the writes go on there.
  void move_to(const std::filesystem::path& dir);

 private:
  void connect_sink();  // sink_'s members call append and append_final
  void append(std::uint64_t k, double t, const particles::StateReader& state);
  void append_final(double t, const particles::StateReader& state);
  void write_at(std::uint64_t offset, const void* data, std::size_t bytes);

  std::filesystem::path path_, temporary_;
  int fd_ = -1;
  std::uint64_t end_ = 0;  // bytes written
  std::vector<StateFileEntry> index_;
  FinalStateUse use_;
  particles::StateSink sink_;
  bool kept_ = false;  // a save refers to the temporary file
};

// The states of a committed file, read in chunks (each read from the disk,
// through the page cache): as StateReader, or one column at a time.
class StoredStates {
 public:
  class State final : public particles::StateReader {
   public:
    std::size_t size() const override { return n_; }
    void read(const Chunk& chunk) const override;
    // Column c (0: x, 1: v, 2: m) in pieces, in order.
    void read_column(int c, const std::function<void(const double*, std::size_t)>& piece) const;
    double time() const { return t_; }

   private:
    friend class StoredStates;
    State(const StoredStates* file, std::string name, const StateFileEntry& e)
        : file_(file), name_(std::move(name)), t_(e.t), n_(e.n), offset_(e.offset), sums_(e.sums) {}
    // RunError unless column c read as `read` matches its checksum.
    void check(int c, std::uint64_t read) const;
    const StoredStates* file_;
    std::string name_;  // "snapshot k" or "the final state", for messages
    double t_;
    std::uint64_t n_, offset_;
    std::array<std::uint64_t, 3> sums_;
  };

  // Opens a committed file; RunError naming it when it is missing, shorter
  // than its index says or not a state file.
  static std::shared_ptr<const StoredStates> open(const std::filesystem::path& path);
  // What is wrong with the state file at path, every column read and checked;
  // nullopt when it is whole (for a resumed run).
  static std::optional<std::string> problem(const std::filesystem::path& path) noexcept;
  // The same for the temporary file of a run saved while it ran: the states a
  // save lists (StateFileWriter::saved()), each column against its checksum.
  static std::optional<std::string> saved_problem(const std::filesystem::path& temporary,
                                                  const std::string& saved) noexcept;
  ~StoredStates();
  StoredStates(const StoredStates&) = delete;
  StoredStates& operator=(const StoredStates&) = delete;

  // The final state, where it was kept (FinalStateUse::keep); else null.
  const State* final_state() const { return final_.empty() ? nullptr : &final_[0]; }
  // Its heaviest cluster, where one was written (FinalStateUse::heaviest).
  std::optional<HeaviestCluster> heaviest_cluster() const;
  const std::vector<State>& snapshots() const { return snapshots_; }  // in order of k

 private:
  StoredStates(std::filesystem::path path, int fd) : path_(std::move(path)), fd_(fd) {}
  void read_at(std::uint64_t offset, void* data, std::size_t bytes) const;

  std::filesystem::path path_;
  int fd_;
  std::vector<State> final_, heaviest_, snapshots_;
};

}  // namespace shockgas::app
