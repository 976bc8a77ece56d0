#pragma once
// Damaged result files given to every reader (finding of a hostile pass:
// `animate`, `info` and `merge` segfaulted inside the HDF5 library on a damaged
// file, with or without a manifest made for it, and `shockgas.load()` killed
// Python). Bytes are changed anywhere in a run's and a shard's result.h5,
// seeded; then info, animate, merge and the Python module's load read it. The
// rules: never a signal (the library runs in a child process,
// result_reader.hpp), never exit 0 where the damage can be seen (the file is
// not as its manifest records), and otherwise 0 or 2, never 1: a file the
// library cannot read is damaged input. (A damage its manifest was written
// for, in data the library does not check, cannot be seen until result.h5
// checks itself.)
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "child_run.hpp"
#include "run_dir_checks.hpp"
#include "shockgas/app/files/manifest.hpp"

namespace shockgas::app::testing {

// What a damaged copy's manifest says.
enum class ManifestKind { original, recomputed, removed };

inline const char* kind_name(ManifestKind k) {
  return k == ManifestKind::original     ? "original manifest"
         : k == ManifestKind::recomputed ? "recomputed manifest"
                                         : "no manifest";
}

class DamagedResults {
 public:
  // A run with frames and a shard of the same small scene, made once per process.
  DamagedResults() : root_(fresh_dir("damaged-results")) {
    write_text(root_ / "scene.toml",
               "[scene]\nname = \"damaged\"\n[initial]\nN = 400\n[particles]\nr = 0.5\nt_end = 20\n"
               "samples = 6\nrealizations = 2\n[continuum]\nsolvers = [\"hopf_lax\"]\ncells = 400\n"
               "[compare]\n[output]\nplots = false\nanimation = true\nanimation_frames = 3\n");
    script_ = root_ / "animation.py";
    write_text(script_,
               "import os, sys\nopen(os.path.join(sys.argv[1], 'animation.png'), 'w').write('frame')\n");
    made("run", {"run", (root_ / "scene.toml").string(), "--out", (root_ / "run").string(), "-q"});
    made("shard", {"run", (root_ / "scene.toml").string(), "--realizations", "0:2", "--out",
                   (root_ / "shard").string(), "-q"});
  }

  // Case `seed`: a copy of the run or the shard, a few bytes of its result.h5
  // changed (half the cases within its first 16 kB, where the library's
  // structures are), its manifest as `kind` says; every reader of it checked.
  void check(unsigned seed, ManifestKind kind) {
    std::mt19937 rng(seed);
    const bool shard = rng() % 3 == 0;
    const fs::path dir =
        root_ / ("case-" + std::to_string(seed) + "-" + std::to_string(static_cast<int>(kind)));
    fs::copy(root_ / (shard ? "shard" : "run"), dir, fs::copy_options::recursive);
    damage(dir / "result.h5", rng);
    if (kind == ManifestKind::recomputed) write_manifest(dir, read_manifest(dir)->scene);
    if (kind == ManifestKind::removed) fs::remove(dir / kManifestFile);
    const std::string what = std::string(kind_name(kind)) + ", seed " + std::to_string(seed);
    const Options stand_in = with_env({{"SHOCKGAS_ANIMATE_SCRIPT", script_.string()}});
    std::vector<std::pair<std::string, std::vector<std::string>>> commands = {
        {"info", {"info", dir.string()}}};
    if (shard)
      commands.push_back(
          {"merge", {"merge", dir.string(), "--out", (dir.string() + "-merged"), "-q", "--no-plots"}});
    else
      commands.push_back({"animate", {"animate", dir.string()}});
    for (const auto& [name, args] : commands) {
      const auto [code, err] = run_child(args, stand_in);
      expect_clean(name, code, err, kind, what);
    }
    if (!shard) loads_.push_back({dir, kind, what});
  }

  // Under AddressSanitizer the module needs the sanitizer runtimes loaded
  // first: the ones this test program was linked with (from /proc/self/maps),
  // preloaded into Python, leak checks off (the interpreter keeps its own).
  static std::string sanitizer_preload() {
#if defined(__SANITIZE_ADDRESS__)
    std::ifstream maps("/proc/self/maps");
    std::set<std::string> runtimes;
    for (std::string line; std::getline(maps, line);) {
      const auto slash = line.find('/');
      if (slash == std::string::npos) continue;
      const std::string path = line.substr(slash);
      const std::string name = fs::path(path).filename().string();
      if (name.rfind("libasan.so", 0) == 0 || name.rfind("libubsan.so", 0) == 0) runtimes.insert(path);
    }
    std::string preload;
    for (const auto& r : runtimes) preload += (preload.empty() ? "" : ":") + r;
    return "LD_PRELOAD='" + preload + "' ASAN_OPTIONS=detect_leaks=0 ";
#else
    return "";
#endif
  }

  // shockgas.load of every run case so far, in one Python: it raises
  // InputError (a ValueError) or loads each, and the interpreter lives on to
  // say which, to the end.
  void check_loads() {
#ifdef SHOCKGAS_PYTHON
    const fs::path module = fs::path(SHOCKGAS_BINARY_DIR) / "python";
    if (loads_.empty() || !fs::exists(module / "shockgas" / "__init__.py") || !fs::exists(SHOCKGAS_PYTHON))
      return;
    const fs::path script = root_ / "load.py", out = root_ / "load.out";
    std::string text = "import shockgas\nfor d in [";
    for (const Load& l : loads_) text += "'" + l.dir.string() + "', ";
    text +=
        "]:\n    try:\n        shockgas.load(d)\n        print('loaded', flush=True)\n"
        "    except shockgas.InputError:\n        print('refused', flush=True)\nprint('end')\n";
    write_text(script, text);
    const std::string command = "PYTHONPATH='" + module.string() + "' " + sanitizer_preload() + "'" +
                                SHOCKGAS_PYTHON + "' '" + script.string() + "' > '" + out.string() + "' 2>&1";
    const int status = std::system(command.c_str());
    std::istringstream said(read_text(out));
    std::string line;
    for (const Load& l : loads_) {
      if (!std::getline(said, line)) line = "(Python ended)";
      EXPECT_TRUE(line == "loaded" || line == "refused") << "load (" << l.what << "): " << line;
      if (l.kind == ManifestKind::original) {
        EXPECT_EQ(line, "refused") << "load (" << l.what << ")";
      }
    }
    EXPECT_TRUE(std::getline(said, line) && line == "end") << read_text(out);
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "Python died:\n" << read_text(out);
#endif
    loads_.clear();
  }

 private:
  void made(const std::string& name, const std::vector<std::string>& args) {
    const auto [code, err] = run_child(args);
    ASSERT_EQ(code, 0) << name << ": " << err;
  }

  static void damage(const fs::path& file, std::mt19937& rng) {
    std::fstream f(file, std::ios::in | std::ios::out | std::ios::binary);
    const std::size_t size = fs::file_size(file);
    const std::size_t limit = rng() % 2 == 0 ? std::min<std::size_t>(size, 16384) : size;
    const int bytes = 1 + static_cast<int>(rng() % 4);
    for (int i = 0; i < bytes; ++i) {
      const auto at = static_cast<std::streamoff>(rng() % limit);
      char c = 0;
      f.seekg(at), f.get(c);
      f.seekp(at), f.put(static_cast<char>(c ^ static_cast<char>(1 + rng() % 255)));
    }
  }

  static void expect_clean(const std::string& name, int code, const std::string& err, ManifestKind kind,
                           const std::string& what) {
    EXPECT_LT(code, 128) << name << " ended by a signal (" << what << "):\n" << err;
    if (kind == ManifestKind::original)
      EXPECT_EQ(code, 2) << name << " of a file its manifest does not match (" << what << "):\n" << err;
    else
      EXPECT_TRUE(code == 0 || code == 2) << name << " (" << what << ") exit " << code << ":\n" << err;
  }

  struct Load {
    fs::path dir;
    ManifestKind kind;
    std::string what;
  };
  fs::path root_, script_;
  std::vector<Load> loads_;
};

}  // namespace shockgas::app::testing
