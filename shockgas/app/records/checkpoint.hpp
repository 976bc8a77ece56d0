#pragma once
// Checkpoints of a run's particle ensembles: the exact records of the
// realizations finished so far (realization_record.hpp), saved in the run's
// output directory so that `shockgas run --resume DIR` runs only the others and
// reduces all of them in index order, as an uninterrupted run does: the same
// result bit for bit.
//
// One file, DIR/checkpoint.bin, written atomically (a temporary file, fsync,
// rename, fsync of the directory): a kill at any moment leaves the previous
// checkpoint or the new one, never a mixture. It holds, in this order:
//   "shockgas checkpoint\n", the format number (u64),
//   texts: shockgas version, git commit, scene path, scene text, the overrides
//   (a count, then each), the resolved parameters, the realization and variant
//   slices of a shard ("" for a whole run),
//   the records (a count, then each as encode() bytes),
//   the wall-clock seconds the run had spent computing when it saved, its
//   earlier interrupted parts included (float64 bits as u64),
//   a checksum (FNV-1a, 64 bits) of every byte before it.
// Numbers and lengths are u64 in the machine's byte order: a checkpoint is
// resumed by the same build on the same kind of machine.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "shockgas/app/records/realization_record.hpp"
#include "shockgas/app/scene/scene.hpp"

namespace shockgas::app {

inline constexpr std::uint64_t kCheckpointFormat = 2;

struct Checkpoint {
  std::string version, commit;  // of the build that wrote it
  std::string scene_path, scene_text;
  std::vector<std::string> overrides;
  std::string resolved;                // resolved_scene_text of the scene
  std::string realizations, variants;  // a shard's slices, as given; "" for a whole run
  std::vector<RealizationRecord> records;
  double seconds = 0;  // wall-clock seconds spent computing up to the save [s]
};

// What a resumed run keeps of its checkpoint.
struct KeptWork {
  std::vector<RealizationRecord> records;
  double seconds = 0;  // Checkpoint::seconds [s]
};

// DIR/checkpoint.bin
std::filesystem::path checkpoint_path(const std::filesystem::path& dir);
// "; continue with: shockgas run --resume DIR": how a message about the
// checkpoint kept in dir ends.
std::string resume_hint(const std::filesystem::path& dir);

// Whether a name in a run directory is a checkpoint's: checkpoint.bin, a
// running realization's state (run_state_file.hpp), or a temporary file of a
// write of either that was killed.
bool is_checkpoint_file(const std::filesystem::path& name);

// The checkpoint of `scene` (this build) with these records.
Checkpoint make_checkpoint(const Scene& scene, const std::string& realizations, const std::string& variants,
                           std::vector<RealizationRecord> records);

// Writes it atomically to checkpoint_path(dir) (creating dir); RunError if it
// cannot, the previous checkpoint then left as it was.
void write_checkpoint(const std::filesystem::path& dir, const Checkpoint& checkpoint);

// Reads checkpoint_path(dir) and checks it: InputError (key "--resume") naming
// what is wrong when there is none, it is damaged (checksum, truncation, not a
// checkpoint, another format) or written by another build (version, commit).
// The file is left as it is.
Checkpoint read_checkpoint(const std::filesystem::path& dir);

// The name of the scene a checkpoint was taken of ([scene] name of its resolved
// parameters).
std::string checkpoint_scene_name(const Checkpoint& checkpoint);

// Removes the checkpoint of dir, if any, with the states of its running
// realizations (run_state_file.hpp): the run's result is written.
void remove_checkpoint(const std::filesystem::path& dir);

}  // namespace shockgas::app
