#include "shockgas/app/cli/lab.hpp"

#include <system_error>

#include "shockgas/app/files/data_dir.hpp"
#include "shockgas/core/error.hpp"
#include "shockgas/lab_files.hpp"

namespace shockgas::app {

namespace fs = std::filesystem;

fs::path lab_directory() {
  const auto data = data_dir();
  std::error_code ec;
  if (data && fs::is_regular_file(*data / "lab" / "index.html", ec)) return *data / "lab";
  return {};
}

std::string write_lab(const std::string& out_dir) {
  const fs::path from = lab_directory();
  if (from.empty()) {
    const std::string missing = kLabMissing;
    if (!missing.empty())
      throw LabMissing(
          "the lab was not built: " + missing +
          "; then configure and build again (cmake -S . -B build && cmake --build build --target lab)");
    std::string tried;
    const auto data = data_dir(&tried);
    throw LabMissing("the lab's page is not in " + (data ? (*data / "lab").string() : tried) +
                     ": build it (cmake --build build --target lab) or install it");
  }
  std::error_code ec;
  fs::create_directories(out_dir, ec);
  if (ec) throw RunError("cannot create " + out_dir + ": " + ec.message());
  for (const fs::directory_entry& f : fs::directory_iterator(from)) {
    if (!f.is_regular_file()) continue;
    fs::copy_file(f.path(), fs::path(out_dir) / f.path().filename(), fs::copy_options::overwrite_existing,
                  ec);
    if (ec)
      throw RunError("cannot write " + (fs::path(out_dir) / f.path().filename()).string() + ": " +
                     ec.message());
  }
  const std::string page = (fs::path(out_dir) / "index.html").string();
  return "the lab in " + out_dir + "/: open " + page + " in a browser (it needs no server and no network)\n";
}

}  // namespace shockgas::app
