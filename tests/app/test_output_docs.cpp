// The output layout as declared (shockgas/app/output/output_layout.hpp), as documented
// (docs/output.md) and as written by a run: the three must agree.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "run_command.hpp"
#include "shockgas/app/output/hdf5_file.hpp"
#include "shockgas/app/output/output_layout.hpp"
#include "shockgas/app/report/plots.hpp"
#include "shockgas/core/initial_condition.hpp"

namespace shockgas::app {
namespace {

namespace fs = std::filesystem;
using Kind = LayoutEntry::Kind;

std::string read_file(const fs::path& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

using testing_support::run;

// Runs `scene` (text) into a fresh directory and returns it; `options`: more of the command line.
fs::path run_scene(const std::string& name, const std::string& scene, std::vector<std::string> options = {}) {
  const fs::path dir = testing_support::fresh_process_directory("shockgas-test-layout-", name);
  std::ofstream(dir / "scene.toml") << scene;
  std::vector<std::string> args = {"run", (dir / "scene.toml").string(), "--out", (dir / "out").string(),
                                   "-q"};
  args.insert(args.end(), options.begin(), options.end());
  EXPECT_EQ(run(args), 0);
  return dir / "out";
}

// Every part a run can write: particles with records, the analysis, two solvers, the comparison
// (t_end = 200, 40 samples: T is fitted on [80, 200], from 10 t_stick on, on 7 of them).
const char* kFullScene =
    "[initial]\nN = 300\n[particles]\nr = 0.5\nt_end = 200\nsamples = 40\nrealizations = 2\nsnapshots = "
    "[5.0, "
    "20.0]\n"
    "histogram_bins = 16\nspacetime = true\nspacetime_frames = 5\n"
    "[continuum]\nsolvers = [\"hopf_lax\", \"godunov\"]\ncells = 300\n[compare]\nfit_window = "
    "4\ndistribution_t_min = 2\n"
    "[output]\nplots = false\n";

const char* kSweepScene =
    "[initial]\nN = 200\n[particles]\nt_end = 20\nsamples = 6\nhistogram_bins = 8\n"
    "[sweep]\nvariants = [\"particles.r=0.5\", \"particles.r=0.9\"]\n[output]\nplots = false\n";

// The frames of an animation: particles and two solvers (plots = false: the record, no movie).
const char* kAnimatedScene =
    "[initial]\nN = 200\n[particles]\nr = 0.5\nt_end = 20\nsamples = 6\n"
    "[continuum]\nsolvers = [\"hopf_lax\", \"godunov\"]\ncells = 200\n"
    "[output]\nplots = false\nanimation = true\nanimation_frames = 5\nanimation_spacing = \"log\"\n";

// The groups and datasets of a file, each with the names of its attributes.
std::vector<std::pair<std::string, std::vector<std::string>>> objects(const Hdf5File& h5) {
  std::set<std::string> paths = {"/"};
  for (const auto& d : h5.datasets())
    for (std::size_t at = d.path.size(); at != std::string::npos && at > 0; at = d.path.rfind('/', at - 1))
      paths.insert(d.path.substr(0, at));
  std::vector<std::pair<std::string, std::vector<std::string>>> out;
  for (const auto& p : paths) {
    std::vector<std::string> names;
    for (const auto& [name, value] : h5.attributes(p)) names.push_back(name);
    out.push_back({p, names});
  }
  return out;
}

// Whether every key of the summary falls under a declared key (declared objects such
// as continuum.<solver>.stats or variants count whole); collects the declarations met.
void expect_declared(const nlohmann::json& node, const std::string& path, std::set<std::string>& seen) {
  if (const LayoutEntry* e = path.empty() ? nullptr : find_in_layout(Kind::summary, path)) {
    seen.insert(e->path);
    return;
  }
  ASSERT_TRUE(node.is_object()) << path << " is not declared";
  for (const auto& [k, v] : node.items()) expect_declared(v, path.empty() ? k : path + "." + k, seen);
}

// The entries of `parts` that a file and its summary show, checked both ways.
void expect_file_follows_layout(const fs::path& out, const std::set<Part>& parts) {
  const Hdf5File h5 = Hdf5File::open((out / "result.h5").string());
  std::set<std::string> seen;
  for (const auto& d : h5.datasets()) {
    const LayoutEntry* e = find_in_layout(Kind::dataset, d.path);
    ASSERT_TRUE(e) << d.path << " is not declared";
    EXPECT_EQ(d.unit, e->unit) << d.path;
    EXPECT_EQ(d.description, e->description) << d.path;
    seen.insert(e->path);
  }
  for (const auto& [object, names] : objects(h5))
    for (const auto& name : names) {
      if (name == "unit" || name == "description") continue;
      const LayoutEntry* e = find_in_layout(Kind::attribute, object + "@" + name);
      ASSERT_TRUE(e) << object << "@" << name << " is not declared";
      seen.insert(e->path);
    }
  expect_declared(nlohmann::json::parse(read_file(out / "summary.json")), "", seen);
  // Every unconditional entry of these parts is written.
  for (const auto& e : output_layout()) {
    if (parts.count(e.part) && e.when.empty()) {
      EXPECT_TRUE(seen.count(e.path)) << e.path << " is declared but was not written";
    }
  }
}

TEST(OutputDocs, DocsOutputMdHoldsTheDeclaredLayout) {
  const std::string doc = read_file(fs::path(SHOCKGAS_SOURCE_DIR) / "docs" / "output.md");
  const std::string begin = "<!-- layout begin -->\n", end = "<!-- layout end -->";
  const auto a = doc.find(begin), b = doc.find(end);
  ASSERT_NE(a, std::string::npos);
  ASSERT_NE(b, std::string::npos);
  EXPECT_EQ(doc.substr(a + begin.size(), b - a - begin.size()), output_layout_markdown())
      << "docs/output.md differs from the declared layout: replace the part between the layout markers with\n"
         "  build/shockgas info --layout";
}

TEST(OutputDocs, ARunWritesTheDeclaredLayout) {
  expect_file_follows_layout(run_scene("full", kFullScene),
                             {Part::provenance, Part::initial, Part::particles, Part::analysis,
                              Part::continuum, Part::compare, Part::theory});
}

// /initial/x, v, m are realization 0 as make_initial_bodies draws it, to the bit
// (each column streams the realization again; only x draws the positions).
TEST(OutputDocs, TheInitialDatasetsAreRealizationZeroAsDrawn) {
  InitialParams p;
  p.N = 3000, p.L = 2500, p.positions = Positions::random, p.velocities = Velocities::gaussian;
  p.amplitude = 0.7, p.remove_mean = true, p.seed = 11;
  const fs::path out = run_scene("initial",
                                 "[initial]\nN = 3000\nL = 2500\npositions = \"random\"\nvelocities = "
                                 "\"gaussian\"\namplitude = 0.7\nremove_mean = true\nseed = 11\n"
                                 "[particles]\nt_end = 1\nsamples = 2\n[output]\nplots = false\n");
  const Bodies drawn = make_initial_bodies(p, 0);
  const Hdf5File h5 = Hdf5File::open((out / "result.h5").string());
  EXPECT_EQ(h5.read("/initial/x"), drawn.x);
  EXPECT_EQ(h5.read("/initial/v"), drawn.v);
  EXPECT_EQ(h5.read("/initial/m"), drawn.m);
}

// The plot script reads only the result file (plots/plot_result.py): it must find
// what it reads, and draw every picture the run's parts call for.
TEST(OutputDocs, ThePlotScriptReadsARunsFiles) {
  const fs::path out = run_scene("plots", kFullScene);
  const std::string script = (plots_dir() / "plot_result.py").string();
  const int status = std::system(("/usr/bin/python3 '" + script + "' '" + out.string() + "'").c_str());
  if (WIFEXITED(status) && WEXITSTATUS(status) == 3)
    GTEST_SKIP() << "matplotlib or h5py missing for /usr/bin/python3";
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "plot_result.py failed";
  for (const char* png :
       {"temperature.png", "velocity_distribution.png", "spacetime.png", "fields.png", "clusters.png"})
    EXPECT_TRUE(fs::exists(out / png)) << png;
}

TEST(OutputDocs, AnAnimatedRunWritesTheDeclaredLayout) {
  expect_file_follows_layout(run_scene("animated", kAnimatedScene), {Part::animation});
}

TEST(OutputDocs, ASweepWritesTheDeclaredLayout) {
  expect_file_follows_layout(run_scene("sweep", kSweepScene), {Part::provenance, Part::sweep});
}

TEST(OutputDocs, AShardWritesTheDeclaredLayout) {
  expect_file_follows_layout(run_scene("shard", kFullScene, {"--realizations", "0:1"}),
                             {Part::provenance, Part::shard});
}

TEST(OutputDocs, EveryDeclaredSummaryKeyIsDocumentedWithItsUnit) {
  const std::string doc = read_file(fs::path(SHOCKGAS_SOURCE_DIR) / "docs" / "output.md");
  int keys = 0;
  for (const auto& e : output_layout()) {
    EXPECT_FALSE(e.description.empty()) << e.path;
    EXPECT_NE(doc.find("| `" + e.path + "` | " + e.unit), std::string::npos) << e.path;
    keys += e.kind == Kind::summary;
  }
  EXPECT_GT(keys, 50);
}

}  // namespace
}  // namespace shockgas::app
