#include "shockgas/app/files/data_dir.hpp"

#include <dlfcn.h>

#include <cstdlib>
#include <vector>

namespace shockgas::app {

namespace fs = std::filesystem;

namespace {

bool holds_plots(const fs::path& dir) {
  std::error_code ec;
  return fs::is_directory(dir / "plots", ec);
}

}  // namespace

fs::path running_file() {
  std::error_code ec;
  fs::path program = fs::read_symlink("/proc/self/exe", ec);
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&running_file), &info) != 0 && info.dli_fname != nullptr) {
    // The program itself is named as it was started (maybe relative); a shared object by its path.
    fs::path object = fs::weakly_canonical(info.dli_fname, ec);
    if (!ec && !object.empty() && object.filename() != program.filename()) return object;
  }
  return program;
}

std::optional<fs::path> data_dir(std::string* tried) {
  if (const char* env = std::getenv("SHOCKGAS_DATA_DIR"); env != nullptr && *env != '\0') {
    if (holds_plots(env)) return fs::path(env);
    if (tried) *tried = std::string(env) + " (SHOCKGAS_DATA_DIR)";
    return std::nullopt;
  }
  const fs::path here = running_file().parent_path();
  const std::vector<fs::path> places = {here / "share" / "shockgas",
                                        here.parent_path() / "share" / "shockgas"};
  std::string list;
  for (const auto& place : places) {
    if (holds_plots(place)) return place.lexically_normal();
    list += (list.empty() ? "" : ", ") + place.lexically_normal().string();
  }
  if (tried) *tried = list;
  return std::nullopt;
}

}  // namespace shockgas::app
