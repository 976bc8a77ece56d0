// Integrity of the results (findings: `shockgas info` crashed inside the HDF5
// library on a damaged file, and gave one message for a missing, truncated,
// non-HDF5 file and a directory): every run directory has a manifest with each
// file's size and SHA-256, checked before the HDF5 library reads a byte.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cstdio>
#include <filesystem>
#include <random>
#include <sstream>
#include <string>

#include "child_run.hpp"
#include "run_dir_checks.hpp"
#include "scene_a_run.hpp"
#include "shockgas/app/cli/info.hpp"
#include "shockgas/app/files/file_problem.hpp"

namespace shockgas::app {
namespace {

using namespace testing;

// One run's directory, made once for the tests below (each copies it).
const fs::path& pristine() {
  static const fs::path dir = scene_a_run("integrity");
  return dir;
}

fs::path copy_of_run(const std::string& name) {
  fs::path dir = fresh_dir("integrity-" + name) / "run";
  fs::copy(pristine(), dir, fs::copy_options::recursive);
  return dir;
}

// `sha256sum FILE` (coreutils): an independent reading of the checksum.
std::string sha256sum(const fs::path& file) {
  std::string line;
  if (FILE* p = popen(("sha256sum '" + file.string() + "'").c_str(), "r")) {
    char buf[256];
    if (fgets(buf, sizeof buf, p)) line = buf;
    pclose(p);
  }
  return line.substr(0, 64);
}

// Overwrites `count` bytes at seeded random places of [from, to) (the damage of
// the finding: a few thousand bytes in the first 200 kB).
void damage(const fs::path& file, std::size_t from, std::size_t to, std::size_t count, unsigned seed) {
  std::fstream f(file, std::ios::in | std::ios::out | std::ios::binary);
  std::mt19937 rng(seed);
  std::uniform_int_distribution<std::size_t> at(from, std::min<std::size_t>(to, fs::file_size(file)) - 1);
  std::uniform_int_distribution<int> byte(0, 255);
  for (std::size_t i = 0; i < count; ++i) {
    f.seekp(static_cast<std::streamoff>(at(rng)));
    f.put(static_cast<char>(byte(rng)));
  }
}

TEST(Integrity, TheManifestListsEveryFileWithItsSizeAndSha256) {
  const fs::path& run = pristine();
  const auto m = read_manifest(run);
  ASSERT_TRUE(m);
  EXPECT_EQ(m->scene, "alpha");
  std::vector<std::string> listed;
  for (const auto& f : m->files) {
    listed.push_back(f.path);
    EXPECT_EQ(f.bytes, fs::file_size(run / f.path)) << f.path;
    EXPECT_EQ(f.sha256, sha256sum(run / f.path)) << f.path;
  }
  EXPECT_EQ(listed, (std::vector<std::string>{"report.html", "report.md", "result.h5", "result.xdmf",
                                              "summary.json"}));
}

TEST(Integrity, InfoReportsADamagedFileBeforeTheHdf5LibraryReadsIt) {
  const fs::path run = copy_of_run("damaged");
  damage(run / "result.h5", 0, 200000, 3000, 7);
  const auto [code, err] = run_child({"info", (run / "result.h5").string()});
  EXPECT_EQ(code, 2) << err;
  EXPECT_NE(err.find("result.h5: damaged: its SHA-256 differs"), std::string::npos) << err;
}

TEST(Integrity, InfoReportsATruncatedFile) {
  const fs::path run = copy_of_run("truncated");
  fs::resize_file(run / "result.h5", fs::file_size(run / "result.h5") / 3);
  const auto [code, err] = run_child({"info", (run / "result.h5").string()});
  EXPECT_EQ(code, 2) << err;
  EXPECT_NE(err.find("result.h5: truncated: "), std::string::npos) << err;
}

TEST(Integrity, InfoNamesWhatIsWrongWithAPath) {
  const fs::path root = fresh_dir("integrity-paths");
  write_text(root / "notes.h5", "not hdf5 at all\n");
  write_text(root / "empty.h5", "");
  fs::create_directories(root / "emptydir");
  ASSERT_EQ(mkfifo((root / "pipe.h5").c_str(), 0644), 0);
  const std::vector<std::pair<std::string, std::string>> cases = {
      {(root / "missing.h5").string(), "missing.h5: no such file"},
      {(root / "emptydir").string(), "emptydir: a directory"},
      {(root / "pipe.h5").string(), "pipe.h5: not a regular file"},
      {(root / "notes.h5").string(), "notes.h5: not an HDF5 file"},
      {(root / "empty.h5").string(), "empty.h5: empty"},
  };
  for (const auto& [path, message] : cases) {
    const auto [code, err] = run_child({"info", path});
    EXPECT_EQ(code, 2) << path << "\n" << err;
    EXPECT_NE(err.find(message), std::string::npos) << err;
  }
}

// A file of layout 1.0 (tests/data/layout-1.0, written before files carried a
// checksum of their own): without its manifest nothing can check it.
TEST(Integrity, AFileWithoutAManifestIsReadWithAWarning) {
  const fs::path run = fresh_dir("integrity-nomanifest") / "run";
  fs::copy(fs::path(SHOCKGAS_SOURCE_DIR) / "tests/data/layout-1.0", run, fs::copy_options::recursive);
  fs::remove(run / kManifestFile);
  const auto [code, err] = run_child({"info", (run / "result.h5").string()});
  EXPECT_EQ(code, 0) << err;
  EXPECT_NE(err.find("warning: "), std::string::npos) << err;
  EXPECT_NE(err.find("integrity cannot be checked"), std::string::npos) << err;
  // A run directory stands for its result.h5.
  EXPECT_EQ(run_child({"info", copy_of_run("dir").string()}).first, 0);
}

// Without a manifest the damage cannot be seen before reading; the library may
// then crash inside the file, and `info` reads it in a child process so that
// only the child dies: a message and exit 2, never a signal. The damage of the
// finding (seeded) made the HDF5 library crash; each seed here must end in a
// clean exit whatever the library does.
TEST(Integrity, ADamagedFileWithoutAManifestNeverCrashesInfo) {
  for (unsigned seed = 1; seed <= 8; ++seed) {
    const fs::path run = copy_of_run("nomanifest-damaged-" + std::to_string(seed));
    fs::remove(run / kManifestFile);
    damage(run / "result.h5", 0, 200000, 3000, seed);
    const auto [code, err] = run_child({"info", (run / "result.h5").string()});
    EXPECT_TRUE(code == 0 || code == 2) << "seed " << seed << ": status " << code << "\n" << err;
  }
}

// `info DIR` checks every file the manifest lists, not only result.h5 (finding:
// an edited summary.json or a deleted picture went unnoticed), and names the
// files the run did not write without failing on them.
TEST(Integrity, InfoChecksEveryFileTheManifestLists) {
  const fs::path run = copy_of_run("all-files");
  const std::size_t listed = read_manifest(run)->files.size();
  const RunFilesCheck before = check_run_files(run.string());
  EXPECT_EQ(before.differences, "");
  EXPECT_NE(before.listing.find("all " + std::to_string(listed) + " intact"), std::string::npos)
      << before.listing;

  { std::ofstream(run / "summary.json", std::ios::app) << " "; }  // one byte more
  fs::remove(run / "report.md");
  write_text(run / "notes.txt", "mine\n");
  const RunFilesCheck after =
      check_run_files((run / "result.h5").string());  // the file stands for its directory
  EXPECT_NE(after.differences.find("summary.json damaged"), std::string::npos) << after.differences;
  EXPECT_NE(after.differences.find("report.md missing"), std::string::npos) << after.differences;
  EXPECT_EQ(after.differences.find("notes.txt"), std::string::npos) << after.differences;
  EXPECT_NE(after.listing.find("notes.txt: not listed"), std::string::npos) << after.listing;
  EXPECT_NE(after.listing.find(std::to_string(listed - 2) + " of " + std::to_string(listed) + " intact"),
            std::string::npos)
      << after.listing;

  {  // `info result.h5` in the run's own directory names it by its path, not "."
    const fs::path here = fs::current_path();
    fs::current_path(run);
    const RunFilesCheck local = check_run_files("result.h5"), dot = check_run_files(".");
    fs::current_path(here);
    EXPECT_EQ(local.directory, fs::canonical(run).string());
    EXPECT_EQ(dot.directory, fs::canonical(run).string());
    EXPECT_EQ(local.listing.rfind("\nfiles of " + fs::canonical(run).string() + " (", 0), 0u)
        << local.listing;
  }

  const auto [code, err] = run_child({"info", run.string()});
  EXPECT_EQ(code, 2) << err;
  EXPECT_NE(err.find(": not as its manifest.json records: "), std::string::npos) << err;
  EXPECT_NE(err.find("(2 of the " + std::to_string(listed) + " files manifest.json lists)"),
            std::string::npos)
      << err;
}

// A manifest with a file's line taken out exempted that file (finding of a
// hostile pass): a file of a name a run writes that its manifest leaves out
// fails info, whichever file it is.
TEST(Integrity, AManifestThatLeavesAFileOutIsRefused) {
  for (const std::string file : {"report.html", "report.md", "result.h5", "result.xdmf", "summary.json"}) {
    const fs::path run = copy_of_run("left-out-" + file);
    const fs::path aside = run.parent_path() / file;
    fs::rename(run / file, aside);
    write_manifest(run, "alpha");  // the manifest as it is with that file's line taken out
    fs::rename(aside, run / file);
    const auto [code, err] = run_child({"info", run.string()});
    EXPECT_EQ(code, 2) << file << "\n" << err;
    EXPECT_NE(err.find(file), std::string::npos) << err;
  }
}

// A run directory whose manifest was removed was described as if whole, its
// other files unchecked and nothing said (finding of a hostile pass).
TEST(Integrity, ARunDirectoryWithoutItsManifestIsSaidToBeUnchecked) {
  const fs::path run = copy_of_run("no-manifest");
  fs::remove(run / "manifest.json");
  const auto [code, err] = run_child({"info", run.string()});
  EXPECT_EQ(code, 0) << err;  // result.h5 is checked by its own checksum
  EXPECT_NE(err.find("has no manifest.json: its files besides result.h5 cannot be checked"),
            std::string::npos)
      << err;
}

// A manifest naming another scene than its result.h5 holds passed info
// (finding of a hostile pass): it vouches for no file then.
TEST(Integrity, AManifestOfAnotherSceneThanItsResultIsRefused) {
  const fs::path run = copy_of_run("other-scene");
  write_manifest(run, "beta");  // every size and SHA-256 right, the scene not
  const auto [code, err] = run_child({"info", run.string()});
  EXPECT_EQ(code, 2) << err;
  EXPECT_NE(err.find("manifest.json names the scene \"beta\", the file holds \"alpha\""), std::string::npos)
      << err;
}

// A result file that cannot be described does not keep info from checking the
// other files (finding: a truncated result.h5 ended info before the edited
// summary.json beside it was named).
TEST(Integrity, ADamagedResultDoesNotHideTheOtherFiles) {
  const fs::path run = copy_of_run("result-and-more");
  fs::resize_file(run / "result.h5", 5000);
  { std::ofstream(run / "summary.json", std::ios::app) << " "; }
  std::ostringstream out;
  try {
    print_info(run.string(), out);
    ADD_FAILURE() << "a truncated result.h5 passed";
  } catch (const FileProblem& e) {
    EXPECT_NE(std::string(e.what()).find("result.h5: truncated"), std::string::npos) << e.what();
  }
  EXPECT_NE(out.str().find("  result.h5: truncated (5000 of the "), std::string::npos) << out.str();
  EXPECT_NE(out.str().find("  summary.json: damaged"), std::string::npos) << out.str();
}

// A file of the same size with other bytes is found by its SHA-256; a link
// the run did not write is named as one, under its own name.
TEST(Integrity, InfoFindsASwappedByteAndNamesALinkAsItself) {
  const fs::path run = copy_of_run("swapped");
  {
    std::fstream f(run / "report.md", std::ios::in | std::ios::out | std::ios::binary);
    char c = 0;
    f.seekg(10), f.get(c), f.seekp(10), f.put(static_cast<char>(c ^ 1));
  }
  fs::create_symlink("/etc/hostname", run / "link");
  const RunFilesCheck check = check_run_files(run.string());
  EXPECT_EQ(check.differences.find("report.md damaged"), 0u) << check.differences;
  EXPECT_NE(check.listing.find("\n  link: not listed (a symbolic link"), std::string::npos) << check.listing;
  EXPECT_EQ(check.directory, run.string());
}

// A manifest that shockgas cannot have written is refused as a whole, before
// any file it names is read: a path out of the directory, one not in the form
// written, a malformed digest, a file listed twice.
TEST(Integrity, AManifestShockgasCannotHaveWrittenIsRefused) {
  const std::vector<std::pair<std::string, std::string>> edits = {
      {"\"report.md\"", "\"../run/report.md\""},
      {"\"report.md\"", "\"./report.md\""},
      {"\"report.md\"", "\"\""},
      {"\"report.md\"", "\"result.h5\""},
  };
  for (std::size_t k = 0; k < edits.size(); ++k) {
    const fs::path run = copy_of_run("manifest-edit-" + std::to_string(k));
    std::string text = read_text(run / kManifestFile);
    const auto at = text.find(edits[k].first);
    ASSERT_NE(at, std::string::npos);
    text.replace(at, edits[k].first.size(), edits[k].second);
    write_text(run / kManifestFile, text);
    const auto [code, err] = run_child({"info", run.string()});
    EXPECT_EQ(code, 2) << edits[k].second << "\n" << err;
    EXPECT_NE(err.find("manifest.json: not a manifest.json written by shockgas: "), std::string::npos) << err;
  }
  const fs::path run = copy_of_run("manifest-digest");
  std::string text = read_text(run / kManifestFile);
  const auto at = text.find("\"sha256\": \"");
  ASSERT_NE(at, std::string::npos);
  text.replace(at + 11, 3, "XYZ");
  write_text(run / kManifestFile, text);
  const auto [code, err] = run_child({"info", run.string()});
  EXPECT_EQ(code, 2) << err;
  EXPECT_NE(err.find("a SHA-256 that is not 64 lowercase hex digits"), std::string::npos) << err;
}

// A run directory whose result.h5 was removed: named as missing, with where
// that is known from, not as "a directory" without one.
TEST(Integrity, ARemovedResultIsNamedAsRemoved) {
  const fs::path run = copy_of_run("no-result");
  fs::remove(run / "result.h5");
  const auto [code, err] = run_child({"info", run.string()});
  EXPECT_EQ(code, 2) << err;
  EXPECT_NE(err.find("result.h5: no such file: the run wrote it, as " + (run / kManifestFile).string() +
                     " records; it was removed since"),
            std::string::npos)
      << err;
}

// In a sweep the variants' files are checked against the sweep's manifest, and
// the detail names that manifest, not the variant's own.
TEST(Integrity, ASweepsFilesAreCheckedAgainstTheManifestThatListsThem) {
  const fs::path root = fresh_dir("integrity-sweep");
  write_text(root / "sweep.toml", std::string(kSceneA) +
                                      "[sweep]\nvariants = [\"particles.r=0.5\", \"particles.r=0.9\"]\n"
                                      "[output]\nplots = false\n");
  const fs::path run = root / "run";
  const auto [made, why] = run_child({"run", (root / "sweep.toml").string(), "--out", run.string(), "-q"});
  ASSERT_EQ(made, 0) << why;
  fs::path variant;
  for (const auto& e : fs::directory_iterator(run))
    if (e.is_directory()) variant = e.path();
  ASSERT_FALSE(variant.empty());
  { std::ofstream(variant / "summary.json", std::ios::app) << " "; }
  const RunFilesCheck check = check_run_files(run.string());
  const std::string name = variant.filename().string() + "/summary.json";
  EXPECT_EQ(check.differences.find(name + " damaged"), 0u) << check.differences;
  EXPECT_NE(check.listing.find("the one " + (run / kManifestFile).string() + " recorded"), std::string::npos)
      << check.listing;
  EXPECT_EQ(check_run_files(variant.string()).differences.find("summary.json damaged"), 0u);
}

// `shockgas animate` of a sweep's variant brings the sweep's manifest up to
// date too (finding: info on the sweep then failed, the variant's manifest and
// report.html no longer as the sweep's manifest recorded them). A stand-in
// animation script writes the picture.
TEST(Integrity, AnAnimatedVariantKeepsItsSweepIntact) {
  const fs::path root = fresh_dir("integrity-animate-variant");
  write_text(root / "sweep.toml", std::string(kSceneA) +
                                      "[sweep]\nvariants = [\"particles.r=0.5\", \"particles.r=0.9\"]\n"
                                      "[output]\nplots = false\nanimation = true\nanimation_frames = 4\n");
  const fs::path run = root / "run", script = root / "animation.py";
  write_text(script,
             "import os, sys\nopen(os.path.join(sys.argv[1], 'animation.png'), 'w').write('frame')\n");
  const Options stand_in = with_env({{"SHOCKGAS_ANIMATE_SCRIPT", script.string()}});
  const auto [made, why] =
      run_child({"run", (root / "sweep.toml").string(), "--out", run.string(), "-q"}, stand_in);
  ASSERT_EQ(made, 0) << why;
  fs::path variant;
  for (const auto& e : fs::directory_iterator(run))
    if (e.is_directory()) variant = e.path();
  ASSERT_FALSE(variant.empty());
  fs::remove(variant / "animation.png");
  const auto [animated, said] = run_child({"animate", variant.string()}, stand_in);
  ASSERT_EQ(animated, 0) << said;
  ASSERT_TRUE(fs::exists(variant / "animation.png"));
  EXPECT_EQ(check_run_files(run.string()).differences, "");
  EXPECT_NE(read_manifest(run)->find(variant.filename().string() + "/animation.png"), nullptr);
  EXPECT_EQ(check_run_files(variant.string()).differences, "");
  // The sweep's own directory has no frames: animate names a variant to give
  // (it said to record frames, though the variants hold them).
  const auto [top, top_said] = run_child({"animate", run.string()}, stand_in);
  EXPECT_EQ(top, 2) << top_said;
  EXPECT_NE(top_said.find("this one is a sweep's, whose frames are its variants': give one of them, e.g. " +
                          run.string() + "/"),
            std::string::npos)
      << top_said;
}

}  // namespace
}  // namespace shockgas::app
