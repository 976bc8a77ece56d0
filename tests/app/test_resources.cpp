// The resource preflight (finding: N = 1e12, histogram_bins = 1e11 and
// samples = 1e9 passed validation and ended in std::bad_alloc, exit 1, no key
// named, an empty directory left): a scene that cannot fit is refused before
// any work, naming the key, the estimate and the limit; the estimate is held
// against the peak memory of real runs.
#include <gtest/gtest.h>
#include <sys/resource.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "child_run.hpp"
#include "run_dir_checks.hpp"
#include "shockgas/app/input/scene_parser.hpp"
#include "shockgas/app/output/result_reader.hpp"
#include "shockgas/app/run/resources.hpp"
#include "shockgas/app/scene/scene.hpp"

namespace shockgas::app {
namespace {

using namespace testing;

const char* kDefault = SHOCKGAS_SOURCE_DIR "/data/scenes/default.toml";

// AddressSanitizer reserves terabytes of address space and doubles the memory
// of a run: neither an address-space limit nor a peak measures the program.
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kSanitized = true;
#else
constexpr bool kSanitized = false;
#endif

TEST(Resources, SizesThatCannotFitAreRefusedNamingTheKeyBeforeAnyWork) {
  const fs::path root = fresh_dir("resources-huge");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"initial.N=1e12", "--set initial.N=1e12: initial.N = 1000000000000 is not allowed"},
      {"particles.histogram_bins=1e11", "particles.histogram_bins = 100000000000 is not allowed"},
      {"particles.samples=1e9", "particles.samples = 1000000000 is not allowed"},
      // keys that multiply another's size are named when they are the ones given (they named
      // particles.spacetime, which the default scene sets)
      {"particles.realizations=1e12", "particles.realizations = 1000000000000 is not allowed"},
      {"particles.spacetime_frames=1e8", "particles.spacetime_frames = 100000000 is not allowed"},
  };
  for (const auto& [set, says] : cases) {
    const auto [code, err] =
        run_child({"run", kDefault, "--set", set, "--out", (root / "out").string(), "-q"});
    EXPECT_EQ(code, 2) << set << "\n" << err;
    EXPECT_NE(err.find(says), std::string::npos) << err;
    EXPECT_NE(err.find("a scene that fits in the memory available: it needs about"), std::string::npos)
        << err;
    EXPECT_NE(err.find(" available ("), std::string::npos) << err;  // the limit and where it comes from
    EXPECT_FALSE(fs::exists(root / "out")) << set;
    EXPECT_TRUE(leftovers(root / "out").empty()) << set;
  }
  // Without [particles] the initial condition's N bodies are still built, for
  // the grid (they ran out of memory inside the run, exit 1, "vector::reserve").
  for (const char* scene : {"white-noise", "riemann"}) {
    const std::string file = std::string(SHOCKGAS_SOURCE_DIR) + "/data/scenes/" + scene + ".toml";
    const auto [code, err] =
        run_child({"run", file, "--set", "initial.N=1e12", "--out", (root / "out").string(), "-q"});
    EXPECT_EQ(code, 2) << scene << "\n" << err;
    EXPECT_NE(err.find("initial.N = 1000000000000 is not allowed"), std::string::npos) << err;
    EXPECT_NE(err.find("it needs about"), std::string::npos) << err;
    EXPECT_FALSE(fs::exists(root / "out")) << scene;
  }
}

// Without an override the refusal names the key the scene gives, not one it
// leaves at its default (particles.samples, which realizations multiplies).
TEST(Resources, TheKeyTheSceneGivesIsNamed) {
  const Scene scene =
      parse_scene("[initial]\nN = 1000\n[particles]\nt_end = 1\nrealizations = 1e12\n", "given.toml");
  try {
    check_memory(scene);
    FAIL() << "10^12 realizations were not refused";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "particles.realizations") << e.what();
  }
  // The engines at work grow with N and with the realizations run at once: of
  // those, the key the command line set.
  const Scene wide = parse_scene("[initial]\nN = 1e9\n[particles]\nt_end = 1\n", "wide.toml",
                                 {"particles.realizations=64", "particles.threads=64"});
  try {
    check_memory(wide);
    FAIL() << "64 engines of 10^9 bodies were not refused";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "particles.realizations") << e.what();
  }
}

TEST(Resources, IntegerKeysTakeWholeFloatsAndRefuseOthers) {
  EXPECT_EQ(load_scene(kDefault, {"initial.N=1e3"}).initial.N, 1000u);
  EXPECT_THROW(load_scene(kDefault, {"initial.N=2.5"}), InputError);
  EXPECT_THROW(load_scene(kDefault, {"particles.histogram_bins=1e1.5"}), InputError);
}

// The limit of the process, not the machine's memory: a run under `ulimit -v`
// is refused naming it.
TEST(Resources, TheProcessLimitIsTheOneThatCounts) {
  if (kSanitized)
    GTEST_SKIP() << "an AddressSanitizer build cannot start under a 400 MiB address-space limit";
  const fs::path root = fresh_dir("resources-ulimit");
  Options o;
  o.in_child = [] {
    const rlimit r{400u << 20, 400u << 20};  // 400 MiB of address space
    setrlimit(RLIMIT_AS, &r);
  };
  const auto [code, err] = run_child({"run", kDefault, "--set", "initial.N=2e7", "--set",
                                      "particles.spacetime=false", "--out", (root / "out").string(), "-q"},
                                     o);
  EXPECT_EQ(code, 2) << err;
  EXPECT_NE(err.find("initial.N = 20000000 is not allowed"), std::string::npos) << err;
  EXPECT_NE(err.find("ulimit -v"), std::string::npos) << err;
  EXPECT_FALSE(fs::exists(root / "out"));
}

// A container's limit: the cgroup (v2) of the process, read under a root of the
// test's own making. 512 MB allowed, 112 MB in use: 400 MB left.
TEST(Resources, ACgroupLimitIsRead) {
  const fs::path root = fresh_dir("resources-cgroup");
  write_text(root / "proc/meminfo", "MemTotal: 64000000 kB\nMemAvailable: 60000000 kB\n");
  write_text(root / "proc/self/cgroup", "0::/job/run\n");
  write_text(root / "proc/self/status", "VmSize: 1000 kB\n");
  write_text(root / "sys/fs/cgroup/memory.max", "max\n");  // the root cgroup: no limit
  write_text(root / "sys/fs/cgroup/job/run/memory.max", "512000000\n");
  write_text(root / "sys/fs/cgroup/job/run/memory.current", "112000000\n");
  const MemoryLimit limit = memory_limit(root);
  if (limit.source.find("ulimit") != std::string::npos)
    GTEST_SKIP() << "a ulimit below 400 MB: " << limit.source;
  EXPECT_EQ(limit.bytes, 400e6);
  EXPECT_EQ(limit.source, "the cgroup's memory.max");
  // Without the cgroup, MemAvailable.
  fs::remove_all(root / "sys");
  EXPECT_EQ(memory_limit(root).bytes, 60000000.0 * 1024);
}

// The estimate against the peak resident memory (ru_maxrss) of real runs, each
// with one item dominating. The preflight must not accept what then fails, so
// the estimate may fall short of the peak by no more than the spread of the
// process base (4 MB), and must not refuse
// what fits, so it may exceed the peak by at most a factor 2 (the copies of a
// record held at the peak vary with the realizations, shockgas/app/run/resources.cpp: the
// model's largest excess, a space-time record at R = 1, is a factor 1.7).
TEST(Resources, TheEstimateHoldsAgainstMeasuredPeakMemory) {
  if (kSanitized) GTEST_SKIP() << "an AddressSanitizer build's peak memory is not the program's";
  const fs::path root = fresh_dir("resources-peak");
  const std::vector<std::pair<std::string, std::string>> scenes = {
      {"particles", "[initial]\nN = 1000000\n[particles]\nt_end = 2\nsamples = 8\nthreads = 1\n"},
      {"merges", "[initial]\nN = 1000000\n[particles]\nr = 0\nt_end = 2\nsamples = 8\nthreads = 1\n"},
      {"hull", "[initial]\nN = 1000000\n[particles]\nr = 0\nsolver = \"hull\"\nt_end = 2\nsamples = 8\n"},
      {"ensemble",
       "[initial]\nN = 500000\n[particles]\nt_end = 2\nsamples = 8\nthreads = 2\nrealizations = 3\n"
       "snapshots = [1]\n"},
      {"spacetime",
       "[initial]\nN = 50000\n[particles]\nt_end = 5\nsamples = 4\nthreads = 1\nrealizations = 2\n"
       "spacetime = true\nspacetime_frames = 200\n"},
      // The histograms: 8e6 values (1600 samples x 5000 bins; 200 x 40000 before, whose exact law,
      // integrated bin by bin, took 5 of the run's 8 s: the same item, the same size).
      {"histogram",
       "[initial]\nN = 1000\n[particles]\nt_end = 5\nsamples = 1600\nthreads = 1\nhistogram_bins = 5000\n"},
      {"continuum",
       "[initial]\nvelocities = \"expression\"\nv0 = \"sin(2*pi*x)\"\ndomain = 1.0\n"
       "[continuum]\nsolvers = [\"hopf_lax\", \"godunov\"]\ncells = 200000\nt_end = 0.01\n"},
      // the continuum alone from 2e6 bodies' velocities averaged on 4096 cells
      {"continuum-noise",
       "[initial]\nN = 2000000\n[continuum]\nsolvers = [\"hopf_lax\"]\ncells = 4096\nt_end = 1\n"},
  };
  for (const auto& [name, text] : scenes) {
    const fs::path file = root / (name + ".toml");
    write_text(file, text + "[output]\nplots = false\n");
    const double estimate = estimate_memory(load_scene(file.string())).total();
    Child run({"run", file.string(), "--out", (root / name).string(), "-q"});
    ASSERT_EQ(run.wait(), 0) << name << "\n" << run.err();
    const double peak = 1024.0 * static_cast<double>(run.peak_memory_kb());
    std::cout << name << ": estimate " << estimate / 1e6 << " MB, peak " << peak / 1e6 << " MB\n";
    EXPECT_GE(estimate, peak - 4e6) << name;
    EXPECT_LE(estimate, 2 * peak) << name;
  }
}

// Bytes of the regular files under dir.
double bytes_under(const fs::path& dir) {
  double sum = 0;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file()) sum += static_cast<double>(e.file_size());
  return sum;
}

// What the files under dir hold uncompressed: each result file's values as
// float64, 8 bytes per value its datasets declare (as result_reader.cpp sizes
// them), and every other file's bytes.
double uncompressed_under(const fs::path& dir) {
  double sum = 0;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    if (!e.is_regular_file()) continue;
    if (e.path().extension() != ".h5") {
      sum += static_cast<double>(e.file_size());
      continue;
    }
    for (const DatasetInfo& d : read_result(e.path()).datasets) {
      double values = 1;
      for (const auto n : d.shape) values *= static_cast<double>(n);
      sum += 8 * values;
    }
  }
  return sum;
}

// The disk estimate against the directories real runs wrote (finding: the
// default scene at N = 1000 wrote 5.31 MB where 4.68 MB were estimated, so a
// disk with room for the estimate filled at the last file, after all the
// work). The estimate is the run's size uncompressed (every value as float64,
// shockgas/app/run/resources.cpp), an upper bound of what deflate writes,
// which depends on the values (result.h5 2.5 to 3.4 times smaller here). It
// must not fall short of the bytes written (a run it accepts must fit), nor
// of the values uncompressed (a dataset it forgot, which deflate may hide in
// the bytes); and must not exceed the values uncompressed by more than a
// factor 2 (a run that fits must not be refused; the plots' share varies with
// the pictures' content, and realization 0's states, counted while their file
// lies beside the results, are gone when they are written: the hull case, 1.8).
// Realization 0's final state goes to its state file only where result.h5
// keeps it (output.final; auto: up to kStoredStateBodies bodies): beyond, the
// file holds its heaviest cluster alone (state_file.hpp), and the disk it
// needs is not asked for. N = 10^7 particles alone once asked 240 MB for it.
TEST(Resources, AFinalStateResultH5DoesNotKeepAsksNoDisk) {
  const fs::path root = fresh_dir("resources-final-state");
  write_text(root / "big.toml", "[initial]\nN = 10000000\n[particles]\nt_end = 10\n");
  const auto states = [](const Scene& scene) {
    double bytes = 0;
    for (const auto& i : estimate_disk(scene, false).items)
      if (i.what.find("realization 0's states") != std::string::npos) bytes += i.bytes;
    return bytes;
  };
  const Scene automatic = load_scene((root / "big.toml").string(), {});
  const Scene always = load_scene((root / "big.toml").string(), {"output.final=always"});
  const Scene kept_small = load_scene((root / "big.toml").string(), {"initial.N=50000"});
  // auto: a final state of at most kStoredStateBodies (merged bodies, r = 0), and the heaviest cluster.
  EXPECT_LE(states(automatic), (kStoredStateBodies + 1) * kBodyBytes);
  EXPECT_GE(states(always), 1e7 * kBodyBytes);
  EXPECT_GE(states(kept_small), 5e4 * kBodyBytes);
}

TEST(Resources, TheDiskEstimateHoldsAgainstWrittenDirectories) {
  const fs::path root = fresh_dir("resources-disk");
  struct Case {
    std::string name, text;         // text: a scene of its own, or "" for the default scene
    std::vector<std::string> sets;  // --set
  };
  const std::vector<std::string> small = {"initial.N=1000", "particles.realizations=1",
                                          "continuum.cells=2000"};
  auto with = [](std::vector<std::string> a, const std::vector<std::string>& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
  };
  const std::vector<Case> cases = {
      {"default", "", small},
      {"default-no-plots", "", with(small, {"output.plots=false"})},
      {"default-sweep", "",
       with(small, {"output.plots=false", R"(sweep.variants=["particles.r=0.5", "particles.r=0.9"])"})},
      {"records",
       "[initial]\nN = 50000\n[particles]\nt_end = 5\nsamples = 20\nsnapshots = [1, 2]\nspacetime = true\n"
       "spacetime_frames = 100\nhistogram_bins = 2000\n[output]\nplots = false\n",
       {}},
      {"ensemble",
       "[initial]\nN = 50000\n[particles]\nt_end = 5\nrealizations = 3\nsnapshots = [1]\n[output]\nplots = "
       "false\n",
       {}},
      {"continuum",
       "[initial]\nvelocities = \"expression\"\nv0 = \"sin(2*pi*x)\"\ndomain = 1.0\n"
       "[continuum]\nsolvers = [\"hopf_lax\", \"godunov\"]\ncells = 50000\nt_end = 0.01\n[output]\nplots = "
       "false\n",
       {}},
      {"hull",
       "[initial]\nN = 100000\n[particles]\nr = 0\nsolver = \"hull\"\nt_end = 2\n[output]\nplots = false\n",
       {}},
  };
  // The plots' share is that of the pictures drawn: without the plotting
  // script's modules none are, and the case with plots does not apply.
  const bool plotting = std::system("/usr/bin/python3 -c 'import matplotlib, h5py' 2>/dev/null") == 0;
  for (const auto& c : cases) {
    if (c.name == "default" && !plotting) continue;
    fs::path file = kDefault;
    if (!c.text.empty()) write_text(file = root / (c.name + ".toml"), c.text);
    const Scene scene = load_scene(file.string(), c.sets);
    const ResourceEstimate e = estimate_disk(scene, scene.output.plots);
    std::vector<std::string> args = {"run", file.string(), "--out", (root / c.name).string(), "-q"};
    for (const auto& s : c.sets) args.push_back("--set"), args.push_back(s);
    const auto [code, err] = run_child(args);
    ASSERT_EQ(code, 0) << c.name << "\n" << err;
    const double written = bytes_under(root / c.name);
    const double uncompressed = uncompressed_under(root / c.name);
    std::cout << c.name << ": estimate " << e.total() / 1e6 << " MB, written " << written / 1e6
              << " MB, uncompressed " << uncompressed / 1e6 << " MB\n";
    for (const auto& i : e.items) std::cout << "  " << i.what << ": " << i.bytes / 1e6 << " MB\n";
    EXPECT_GE(e.total(), written) << c.name;
    EXPECT_GE(e.total(), uncompressed) << c.name;
    // The final clusters are counted at their worst case, a gas of pairs (N / 2
    // per realization), which a gas past its first collisions is far from: the
    // factor 2 holds for the rest.
    double clusters_bound = 0;
    for (const auto& i : e.items) clusters_bound += i.key == "particles.final_clusters" ? i.bytes : 0.0;
    EXPECT_LE(e.total() - clusters_bound, 2 * uncompressed) << c.name;
  }
}

}  // namespace
}  // namespace shockgas::app
