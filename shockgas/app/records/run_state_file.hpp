#pragma once
// The saved state of one running realization (shockgas/particles/run_state.hpp), kept
// beside the run's checkpoint (checkpoint.hpp) as DIR/checkpoint.run-E-K.bin
// (ensemble E, realization K): what `shockgas run --resume DIR` continues that
// realization from instead of starting it again.
//
// The file, written atomically (a temporary file, fsync, rename, fsync of the
// directory: a kill leaves the previous state or the new one):
//   "shockgas run state\n", the format number (u64),
//   texts: shockgas version, git commit, the resolved scene text,
//   ensemble, index (u64), the simulated time reached and the share of the
//   work done (doubles), the save of its states file (text, "" for none:
//   state_file.hpp), then the state's bytes,
//   a checksum of every byte before it (FNV-1a over 64-bit words, stream_hash).
// Written as the engine hands it over, from its own arrays (no copy of the
// state is made), and read back the same way.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "shockgas/particles/run_state.hpp"

namespace shockgas::app {

inline constexpr std::uint64_t kRunStateFormat = 1;

struct RunStateHeader {
  std::string version, commit;  // of the build that wrote it
  std::string resolved;         // resolved_scene_text of the run's scene
  std::uint64_t ensemble = 0, index = 0;
  double time = 0;      // simulated time reached
  double fraction = 0;  // share of the realization's work done
  std::string sink;     // where its states file stood (StateFileWriter::saved), or ""
};

// DIR/checkpoint.run-E-K.bin
std::filesystem::path run_state_path(const std::filesystem::path& dir, std::uint64_t ensemble,
                                     std::uint64_t index);

// Whether a name (relative to the run directory) is that of a state file.
bool is_run_state_file(const std::filesystem::path& name);

// Writes header and the state write(out) produces atomically to
// run_state_path(dir, ...); RunError if it cannot (the previous file is left).
void write_run_state(const std::filesystem::path& dir, const RunStateHeader& header,
                     const std::function<void(particles::RunStateWriter&)>& write);

// The headers of the state files in dir; InputError (key "--resume") naming the
// file for one that is not a state file of this format.
std::vector<RunStateHeader> read_run_state_headers(const std::filesystem::path& dir);

// The header of one state file; nullopt if there is none (InputError as above
// for one that is not a state file of this format).
std::optional<RunStateHeader> read_run_state_header(const std::filesystem::path& file);

// Checks a state file's checksum over the whole file: InputError "--resume"
// naming the file if it does not match or the file is cut short.
void check_run_state(const std::filesystem::path& file);

// A state file opened for resuming: checked (check_run_state) unless checked
// already, then read after its header.
std::unique_ptr<particles::RunStateReader> open_run_state(const std::filesystem::path& file,
                                                          bool checked = false);

// Removes every state file of dir (and temporaries of interrupted writes).
void remove_run_states(const std::filesystem::path& dir);

}  // namespace shockgas::app
