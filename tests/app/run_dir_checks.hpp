#pragma once
// What the tests of the run directory assert: a directory is whole (every file
// of its manifest present with its size and SHA-256, nothing else) and holds a
// named scene's results, and nothing of a run is left beside it.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "process_temp_path.hpp"
#include "shockgas/app/files/manifest.hpp"
#include "shockgas/app/files/sha256.hpp"
#include "shockgas/app/records/checkpoint.hpp"

namespace shockgas::app::testing {

namespace fs = std::filesystem;

// "" if dir is whole and holds scene's results, else what is wrong.
inline std::string whole_run(const fs::path& dir, const std::string& scene) {
  if (!fs::is_directory(dir)) return dir.string() + " is missing";
  std::optional<Manifest> m;
  try {
    m = read_manifest(dir);
  } catch (const std::exception& e) {
    return e.what();
  }
  if (!m) return "no manifest.json in " + dir.string();
  if (m->scene != scene) return "the results of \"" + m->scene + "\", not \"" + scene + "\"";
  for (const auto& f : m->files) {
    const fs::path file = dir / f.path;
    if (!fs::is_regular_file(file)) return f.path + " is missing";
    if (fs::file_size(file) != f.bytes || sha256_of_file(file) != f.sha256) return f.path + " differs";
  }
  for (const auto& entry : fs::recursive_directory_iterator(dir))
    if (entry.is_regular_file()) {
      const std::string rel = fs::relative(entry.path(), dir).generic_string();
      // checkpoint.bin and the running realizations' states: an interrupted run's
      // checkpoint beside the results it leaves (checkpoint.hpp).
      if (rel != kManifestFile && !is_checkpoint_file(rel) && !m->find(rel))
        return rel + " is not in the manifest";
    }
  return "";
}

// The entries beside target that a run into it makes (".NAME.tmp-*", ".NAME.lock", ...).
inline std::vector<std::string> leftovers(const fs::path& target) {
  std::vector<std::string> out;
  const std::string prefix = "." + target.filename().string() + ".";
  for (const auto& entry : fs::directory_iterator(target.parent_path()))
    if (entry.path().filename().string().rfind(prefix, 0) == 0)
      out.push_back(entry.path().filename().string());
  return out;
}

inline std::string read_text(const fs::path& file) {
  std::ifstream in(file);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

inline void write_text(const fs::path& file, const std::string& text) {
  fs::create_directories(file.parent_path());
  std::ofstream(file) << text;
}

// Eight bytes of file at offset overwritten with a number no run writes there.
inline void overwrite_eight_bytes(const fs::path& file, std::uint64_t offset) {
  std::fstream f(file, std::ios::binary | std::ios::in | std::ios::out);
  f.seekp(static_cast<std::streamoff>(offset));
  const double garbage = -3.25e106;
  f.write(reinterpret_cast<const char*>(&garbage), sizeof garbage);
}

// A fresh directory for one test, of this process alone (test binaries of
// other builds may run at the same time).
inline fs::path fresh_dir(const std::string& name) {
  return shockgas::testing_support::fresh_process_directory("shockgas-test-", name);
}

// Two small scenes of different names (a few tenths of a second each).
inline const char* kSceneA =
    "[scene]\nname = \"alpha\"\n[initial]\nN = 500\n[particles]\nr = 0.5\nt_end = 50\nsamples = 8\n"
    "[continuum]\nsolvers = [\"hopf_lax\", \"godunov\"]\ncells = 500\n[compare]\n";
inline const char* kSceneB =
    "[scene]\nname = \"beta\"\n[initial]\nN = 800\n[particles]\nr = 0.7\nt_end = 80\nsamples = 10\n"
    "histogram_bins = 20\n[continuum]\nsolvers = [\"hopf_lax\", \"godunov2\"]\ncells = 800\n[compare]\n";

// A plotting script for the tests (SHOCKGAS_PLOT_SCRIPT): writes its pid beside
// the directory it draws into, one picture named after the scene, and, after
// `seconds`, a second one.
inline fs::path fake_plot_script(const fs::path& dir, double seconds) {
  fs::path script = dir / "fake_plot.py";
  write_text(
      script,
      "import json, os, sys, time\n"
      "d = sys.argv[1]\n"
      "open(os.path.join(os.path.dirname(os.path.abspath(d)), 'plotter.pid'), 'w').write(str(os.getpid()))\n"
      "scene = json.load(open(os.path.join(d, 'summary.json')))['scene']\n"
      "open(os.path.join(d, scene + '.png'), 'w').write('picture')\n"
      "time.sleep(" +
          std::to_string(seconds) +
          ")\n"
          "open(os.path.join(d, 'late.png'), 'w').write('late')\n");
  return script;
}

}  // namespace shockgas::app::testing
