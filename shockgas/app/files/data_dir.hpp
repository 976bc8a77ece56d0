#pragma once
// Where shockgas finds what it reads besides a scene: its plotting package and
// its scenes. Looked up from where the code itself lies, so that an installed,
// moved or packaged shockgas needs no path compiled in:
//
//   $SHOCKGAS_DATA_DIR                      if set (and then nothing else)
//   D/share/shockgas, D/../share/shockgas   D = the folder of the file holding this
//                                           code: the command (bin/ or the build
//                                           tree) or the Python module's folder
//
// The first that holds plots/ wins. Installed: PREFIX/share/shockgas
// (cmake/Install.cmake); the build tree links build/share/shockgas into the
// sources; the Python package carries its own share/shockgas.
#include <filesystem>
#include <optional>
#include <string>

namespace shockgas::app {

// The folder holding plots/ and scenes/, or nothing with the places tried in `tried`.
std::optional<std::filesystem::path> data_dir(std::string* tried = nullptr);

// The file the code runs from: the command, or the shared object (Python module, libshockgas).
std::filesystem::path running_file();

}  // namespace shockgas::app
