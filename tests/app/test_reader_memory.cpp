// The memory of the process that reads a result file (result_reader.hpp) is
// sized by what the file declares, not by its bytes: with deflate a file holds
// up to 1032 times its bytes of values (finding: a reading process limited to
// 3 x the file's bytes + 512 MiB refused a sound file of 0.34 MB holding
// 4e7 zeros as "damaged: std::bad_alloc"). A file that declares more than its
// bytes can hold, or more than the memory available, is refused before a value
// is read (exit 2).
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "run_dir_checks.hpp"
#include "shockgas/app/files/file_problem.hpp"
#include "shockgas/app/output/hdf5_file.hpp"
#include "shockgas/app/output/layout_version.hpp"
#include "shockgas/app/output/result_reader.hpp"
#include "shockgas/version.hpp"

namespace shockgas::app {
namespace {

namespace fs = std::filesystem;

const ValueFilter kEveryValue = [](const std::string&) { return true; };

// A result file of `padding` random doubles in [0, 1) (7 of their 8 bytes
// incompressible: the file's bytes)
// and /declared, `declared` doubles whose chunks are never written: a sound
// dataset that reads as its fill value 0, held in no bytes at all.
fs::path declaring_file(const std::string& name, std::uint64_t declared, std::size_t padding) {
  fs::path file = testing::fresh_dir(name) / "result.h5";
  fs::create_directories(file.parent_path());
  Hdf5File h5 = Hdf5File::create(file.string());
  h5.set_attribute("/", "layout_version", layout_version_text());
  h5.set_attribute("/", "shockgas_version", kVersion);  // as every writer's provenance
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::vector<double> noise(padding);
  for (double& x : noise) x = uniform(rng);
  h5.write("/padding", noise.data(), {padding}, Storage::float64, "1", "random bytes");
  { const Hdf5File::Writer unwritten = h5.start("/declared", declared, Storage::float64, "1", "fill value"); }
  h5.close();  // its own checksum: the file is as written
  return file;
}

// What read_result says of `file` (every value asked for) in a child process
// whose address space may grow `room` bytes beyond what it holds now: "" when
// it reads the file, else the FileProblem's problem and detail.
std::string read_within(const fs::path& file, rlim_t room) {
  int fds[2];
  if (pipe(fds) != 0) return "pipe failed";
  const pid_t pid = fork();
  if (pid == 0) {
    close(fds[0]);
    long pages = 0;
    if (FILE* statm = fopen("/proc/self/statm", "r")) {
      if (fscanf(statm, "%ld", &pages) != 1) pages = 0;
      fclose(statm);
    }
    const rlim_t now = static_cast<rlim_t>(pages) * static_cast<rlim_t>(sysconf(_SC_PAGESIZE));
    const rlimit limit{now + room, now + room};
    setrlimit(RLIMIT_AS, &limit);
    std::string said;
    try {
      read_result(file, kEveryValue);
    } catch (const FileProblem& e) {
      said = e.problem() + ": " + e.detail();
    } catch (const std::exception& e) {
      said = std::string("not a FileProblem: ") + e.what();
    }
    if (!said.empty() && write(fds[1], said.data(), said.size()) < 0) _exit(1);
    _exit(0);
  }
  close(fds[1]);
  std::string said;
  char buffer[4096];
  for (ssize_t n; (n = read(fds[0], buffer, sizeof buffer)) > 0;)
    said.append(buffer, static_cast<std::size_t>(n));
  close(fds[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) && WEXITSTATUS(status) == 0 ? said : "the child failed: " + said;
}

TEST(ReaderMemory, AFileOfValuesAThousandTimesItsBytesIsRead) {
  const std::uint64_t values = 40'000'000;  // 320 MB as float64
  const fs::path file = declaring_file("reader-memory-expanding", values, 50'000);
  const double bytes = static_cast<double>(fs::file_size(file));
  // The premise: two copies of the values (the library's read and its frame)
  // do not fit in the reading process sized by the file's bytes alone.
  ASSERT_GT(2 * 8 * static_cast<double>(values), 3 * bytes + 512.0 * (1 << 20));
  const ResultContents contents = read_result(file, kEveryValue);
  const std::vector<double>& read = contents.values.at("/declared");
  ASSERT_EQ(read.size(), values);
  EXPECT_TRUE(std::all_of(read.begin(), read.end(), [](double x) { return x == 0.0; }));
  EXPECT_EQ(contents.values.at("/padding").size(), 50'000u);
}

TEST(ReaderMemory, ValuesBeyondWhatDeflateCanPackIntoTheFileAreDamage) {
  const fs::path file = declaring_file("reader-memory-deflate", 1'000'000'000, 1000);  // 8 GB in 20 kB
  try {
    read_result(file, kEveryValue);
    FAIL() << "8 GB of values declared in a file of " << fs::file_size(file) << " bytes were read";
  } catch (const FileProblem& e) {
    EXPECT_EQ(e.problem(), "damaged");
    EXPECT_NE(e.detail().find("dataset /declared declares 1e+09 values"), std::string::npos) << e.detail();
  }
  // Its layout alone, which declares the values without them, is read.
  const ResultContents layout = read_result(file);
  const auto declared = std::find_if(layout.datasets.begin(), layout.datasets.end(),
                                     [](const DatasetInfo& d) { return d.path == "/declared"; });
  ASSERT_NE(declared, layout.datasets.end());
  EXPECT_EQ(declared->shape, (std::vector<std::uint64_t>{1'000'000'000}));
}

TEST(ReaderMemory, ValuesThatCannotBeHeldInTheMemoryAvailableAreRefused) {
  // 1.6 GB declared in a file of 2 MB (within deflate's 1032 to 1), read
  // with 1 GiB of address space to spare: its five copies cannot be held.
  const fs::path file = declaring_file("reader-memory-room", 200'000'000, 300'000);
  const std::string said = read_within(file, rlim_t{1} << 30);
  EXPECT_EQ(said.rfind("too large to read: its datasets declare 1.6 GB of values", 0), 0u) << said;
  EXPECT_NE(said.find("ulimit -v (address space)"), std::string::npos) << said;
}

}  // namespace
}  // namespace shockgas::app
