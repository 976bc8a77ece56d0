#pragma once
// result.h5 and summary.json of one output directory, written under temporary
// names and renamed when complete, so that an interrupted or failed run never
// leaves a file that looks whole.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

namespace shockgas::app {

// Creates dir (InputError naming --out if it cannot). The temporary files are
// removed if the run fails or is interrupted by a thrown exception (destructor),
// or by SIGINT, SIGTERM where the host asked for it
// (remove_partial_outputs_on_signals). Nests (a sweep holds one per variant
// inside its own); runs on several threads may each hold their own.
class PartialOutputs {
 public:
  explicit PartialOutputs(const std::filesystem::path& dir);
  ~PartialOutputs();
  PartialOutputs(const PartialOutputs&) = delete;
  PartialOutputs& operator=(const PartialOutputs&) = delete;
  const std::string& h5_path() const { return h5_tmp_; }  // where to write result.h5 now
  // Writes summary.json and renames both files to their final names.
  void commit(const nlohmann::ordered_json& summary);

 private:
  std::filesystem::path dir_;
  std::string h5_tmp_, json_tmp_;
};

// For a host that leaves SIGINT and SIGTERM to shockgas (the command line):
// handlers that remove the temporary files of every open PartialOutputs, then
// end the process by the same signal; while a run keeps checkpoints, they ask
// it for a checkpoint instead (checkpointer.hpp). A host with its own handlers (a Python
// session) stops runs by an interrupt request instead (core/interrupt.hpp).
void remove_partial_outputs_on_signals();

}  // namespace shockgas::app
