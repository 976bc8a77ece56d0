#include "shockgas/app/output/partial_outputs.hpp"

#include <unistd.h>

#include <fstream>

#include "shockgas/core/error.hpp"

namespace shockgas::app {

namespace fs = std::filesystem;

PartialOutputs::PartialOutputs(const fs::path& dir) : dir_(dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw InputError("--out", to_text(dir.string()), "a directory that can be created and written");
  const std::string tag = ".partial-" + std::to_string(getpid());
  h5_tmp_ = (dir / "result.h5").string() + tag;
  json_tmp_ = (dir / "summary.json").string() + tag;
}

PartialOutputs::~PartialOutputs() {
  std::error_code ec;
  fs::remove(h5_tmp_, ec);  // no-op once renamed
  fs::remove(json_tmp_, ec);
}

void PartialOutputs::commit(const nlohmann::ordered_json& summary) {
  {
    std::ofstream out(json_tmp_);
    out << summary.dump(2) << "\n";
    if (!out) throw RunError("cannot write " + json_tmp_);
  }
  fs::rename(h5_tmp_, dir_ / "result.h5");
  fs::rename(json_tmp_, dir_ / "summary.json");
}

}  // namespace shockgas::app
