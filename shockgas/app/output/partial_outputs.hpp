#pragma once
// result.h5 and summary.json of one output directory, written under temporary
// names and renamed when complete, so that an interrupted or failed run never
// leaves a file that looks whole.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

namespace shockgas::app {

// Creates dir (InputError naming --out if it cannot). The temporary files are
// removed if the run fails or is interrupted (Interrupted, shockgas/core/interrupt.hpp,
// unwinds through the destructor). Nests (a sweep holds one per variant
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

}  // namespace shockgas::app
