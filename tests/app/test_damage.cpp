// A result file alone, away from its directory's manifest, tells that it is
// damaged (issue: of ten seeded damages `info` read four as sound). Each file
// carries its own SHA-256 (own_checksum.hpp), every dataset Fletcher32 and its
// metadata the library's checksums (hdf5_file.hpp); `info FILE` checks the
// first and reads every chunk. A damage anywhere must end in exit 2, never 0,
// never a signal.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>

#include "child_run.hpp"
#include "run_dir_checks.hpp"
#include "scene_a_run.hpp"
#include "shockgas/app/files/own_checksum.hpp"
#include "shockgas/app/output/hdf5_file.hpp"
#include "shockgas/app/output/layout_version.hpp"

namespace shockgas::app {
namespace {

using namespace testing;

// One run's result.h5, made once; the tests damage copies of it, alone in a directory.
const fs::path& pristine() {
  static const fs::path file = scene_a_run("damage") / "result.h5";
  return file;
}

fs::path lone_copy(const std::string& name) {
  fs::path file = fresh_dir("damage-" + name) / "result.h5";
  fs::create_directories(file.parent_path());
  fs::copy_file(pristine(), file);
  return file;
}

// Flips `count` bytes (each XORed with a nonzero byte, so each differs) at
// seeded random offsets of [from, to).
void flip(const fs::path& file, std::uint64_t from, std::uint64_t to, std::size_t count, unsigned seed) {
  std::fstream f(file, std::ios::in | std::ios::out | std::ios::binary);
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<std::uint64_t> at(from, to - 1);
  std::uniform_int_distribution<int> mask(1, 255);
  for (std::size_t i = 0; i < count; ++i) {
    const auto offset = static_cast<std::streamoff>(at(rng));
    f.seekg(offset);
    const int byte = f.get();
    f.seekp(offset);
    f.put(static_cast<char>(byte ^ mask(rng)));
  }
}

TEST(Damage, ASoundFileAloneIsReadAsSound) {
  const fs::path file = lone_copy("sound");
  const auto [code, err] = run_child({"info", file.string()});
  EXPECT_EQ(code, 0) << err;
  EXPECT_EQ(err.find("warning"), std::string::npos) << err;  // its own checksum checked it
}

// 60 seeds, each with 1, 8 and 512 flipped bytes anywhere in the file: exit 2
// ("damaged") every time; the status of a signal would be 128 + its number.
TEST(Damage, EverySeededDamageOfAFileAloneEndsInExit2) {
  const std::uint64_t size = fs::file_size(pristine());
  for (const std::size_t count : {1, 8, 512})
    for (unsigned seed = 1; seed <= 60; ++seed) {
      const fs::path file = lone_copy("random");
      flip(file, 0, size, count, seed);
      const auto [code, err] = run_child({"info", file.string()});
      ASSERT_EQ(code, 2) << count << " bytes, seed " << seed << "\n" << err;
      // "damaged", or "not an HDF5 file" where the damage broke its first bytes
      ASSERT_TRUE(err.find(": damaged") != std::string::npos ||
                  err.find(": not an HDF5 file") != std::string::npos)
          << count << " bytes, seed " << seed << "\n"
          << err;
    }
}

// A chunk damaged before the file's own checksum was taken (the checksum then
// agrees with the damage): its Fletcher32 still refuses it, and info names the dataset.
TEST(Damage, AChunkDamagedBeforeTheFileChecksumIsNamedByItsFletcher32) {
  std::vector<ChunkExtent> chunks;
  {
    const Hdf5File h5 = Hdf5File::open(pristine().string());
    chunks = h5.chunk_extents();
  }
  ASSERT_FALSE(chunks.empty());
  const auto target = std::find_if(chunks.begin(), chunks.end(),
                                   [](const ChunkExtent& c) { return c.dataset == "/continuum/godunov/v"; });
  ASSERT_NE(target, chunks.end());
  for (unsigned seed = 1; seed <= 5; ++seed) {
    const fs::path file = lone_copy("chunk");
    flip(file, target->offset, target->offset + target->bytes, 1, seed);
    write_own_checksum(file);
    const auto [code, err] = run_child({"info", file.string()});
    EXPECT_EQ(code, 2) << "seed " << seed << "\n" << err;
    EXPECT_NE(err.find("dataset /continuum/godunov/v"), std::string::npos) << "seed " << seed << "\n" << err;
  }
}

// The file's attributes (its scene, provenance, layout version) are the last
// metadata written, at its end: a byte flipped there before the file's own
// checksum was taken fails the attribute heap's checksum, which is a damaged
// file (it was read as intact, with empty provenance, exit 0). 32 seeded
// single flips in the last 1024 bytes.
TEST(Damage, AttributesDamagedBeforeTheFileChecksumAreADamagedFile) {
  const std::uint64_t size = fs::file_size(pristine());
  for (unsigned seed = 1; seed <= 32; ++seed) {
    const fs::path file = lone_copy("attributes");
    flip(file, size - 1024, size, 1, seed);
    write_own_checksum(file);
    const auto [code, err] = run_child({"info", file.string()});
    EXPECT_EQ(code, 2) << "seed " << seed << "\n" << err;
    EXPECT_NE(err.find(": damaged"), std::string::npos) << "seed " << seed << "\n" << err;
  }
}

// A string attribute lives in the library's global heap, which has no checksum
// of its own: a byte changed there before the file's own checksum was taken
// (the layout version's "3" made a "2": another meaning for n_clusters) was
// read as intact. /@attributes_sha256 holds every attribute's SHA-256.
TEST(Damage, AnAttributeChangedBeforeTheFileChecksumIsADamagedFile) {
  const fs::path file = lone_copy("attribute-text");
  std::string bytes;
  {
    std::ifstream in(file, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  const std::string version = layout_version_text() + std::string(1, '\0');
  const std::size_t at = bytes.find(version, kOwnChecksumBytes);
  ASSERT_NE(at, std::string::npos);
  {
    std::fstream out(file, std::ios::in | std::ios::out | std::ios::binary);
    out.seekp(static_cast<std::streamoff>(at));
    out.put('2');
  }
  write_own_checksum(file);
  const auto [code, err] = run_child({"info", file.string()});
  EXPECT_EQ(code, 2) << err;
  EXPECT_NE(err.find("its attributes are not those whose SHA-256 its writer stored"), std::string::npos)
      << err;
}

// Bytes appended after the file's end, its own checksum taken again over them:
// the library reads the file as before (it was read as intact, exit 0), but
// its superblock records where the file ends.
TEST(Damage, BytesAppendedAfterItsEndAreADamagedFile) {
  for (const std::size_t extra : {1, 7, 4096}) {
    const fs::path file = lone_copy("appended");
    {
      std::ofstream out(file, std::ios::binary | std::ios::app);
      out << std::string(extra, 'x');
    }
    write_own_checksum(file);
    const auto [code, err] = run_child({"info", file.string()});
    EXPECT_EQ(code, 2) << extra << "\n" << err;
    EXPECT_NE(err.find(std::to_string(extra) + " bytes after the end of file its HDF5 superblock records"),
              std::string::npos)
        << err;
  }
}

// The damage of the file's own checksum block alone is a damage too.
TEST(Damage, ADamagedChecksumBlockIsADamagedFile) {
  const fs::path file = lone_copy("block");
  flip(file, 0, kOwnChecksumBytes, 1, 3);
  const auto [code, err] = run_child({"info", file.string()});
  EXPECT_EQ(code, 2) << err;
  EXPECT_NE(err.find("damaged"), std::string::npos) << err;
}

// A file of a newer major layout is refused, exit 2, saying which layouts this build reads.
TEST(Damage, AFileOfANewerMajorLayoutIsRefused) {
  const fs::path file = fresh_dir("damage-newer") / "result.h5";
  fs::create_directories(file.parent_path());
  {
    Hdf5File h5 = Hdf5File::create(file.string());
    h5.set_attribute("/", "layout_version", std::to_string(kLayoutVersion.major + 1) + ".0");
    h5.close();
  }
  const auto [code, err] = run_child({"info", file.string()});
  EXPECT_EQ(code, 2) << err;
  EXPECT_NE(err.find("written in layout " + std::to_string(kLayoutVersion.major + 1) + ".0"),
            std::string::npos)
      << err;
  EXPECT_NE(err.find("this one reads layouts 1.0 to " + std::to_string(kLayoutVersion.major) + ".x"),
            std::string::npos)
      << err;
}

// An empty layout_version is no version: refused as not major.minor (it was read as 1.0).
TEST(Damage, AnEmptyLayoutVersionIsRefused) {
  const fs::path file = fresh_dir("damage-empty-version") / "result.h5";
  fs::create_directories(file.parent_path());
  {
    Hdf5File h5 = Hdf5File::create(file.string());
    h5.set_attribute("/", "layout_version", "");
    h5.close();
  }
  const auto [code, err] = run_child({"info", file.string()});
  EXPECT_EQ(code, 2) << err;
  EXPECT_NE(err.find("its layout_version \"\" is not major.minor"), std::string::npos) << err;
}

// `h5dump -p` (hdf5-tools) shows every dataset chunked and filtered by shuffle,
// deflate and Fletcher32: the properties as another program reads them.
TEST(Damage, H5dumpShowsEveryDatasetChunkedAndFiltered) {
  std::string dump;
  if (FILE* p = popen(("h5dump -p -H '" + pristine().string() + "'").c_str(), "r")) {
    char buf[4096];
    while (fgets(buf, sizeof buf, p)) dump += buf;
    pclose(p);
  }
  ASSERT_FALSE(dump.empty()) << "h5dump (Debian: hdf5-tools) gave nothing";
  std::size_t datasets = 0;
  for (std::size_t at = dump.find("DATASET \""); at != std::string::npos;
       at = dump.find("DATASET \"", at + 1)) {
    const std::size_t end = dump.find("DATASET \"", at + 1);
    const std::string block = dump.substr(at, end == std::string::npos ? std::string::npos : end - at);
    const std::string name = block.substr(0, block.find('\n'));
    for (const char* property :
         {"CHUNKED", "PREPROCESSING SHUFFLE", "COMPRESSION DEFLATE", "CHECKSUM FLETCHER32"})
      EXPECT_NE(block.find(property), std::string::npos) << name << " lacks " << property;
    ++datasets;
  }
  EXPECT_GT(datasets, 30u);
}

}  // namespace
}  // namespace shockgas::app
