// The layouts a reader reads (docs/output.md, "Layout version"): a run
// directory of layout 1.0 (tests/data/layout-1.0, written by shockgas 0.1.0
// before the layout was versioned: float64 everywhere, no filters, no checksum
// of its own) is read as it is, by info (against its manifest), by load, and
// `upgrade` says so.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "child_run.hpp"
#include "run_dir_checks.hpp"
#include "shockgas/app/cli/upgrade.hpp"
#include "shockgas/app/output/hdf5_file.hpp"
#include "shockgas/app/output/layout_version.hpp"
#include "shockgas/app/run/captured_outputs.hpp"

namespace shockgas::app {
namespace {

using namespace testing;

fs::path layout_1_run() {
  fs::path run = fresh_dir("layout-1.0") / "run";
  fs::copy(fs::path(SHOCKGAS_SOURCE_DIR) / "tests/data/layout-1.0", run, fs::copy_options::recursive);
  return run;
}

TEST(LayoutVersions, InfoReadsARunDirectoryOfLayout1AgainstItsManifest) {
  const fs::path run = layout_1_run();
  const auto [code, err] = run_child({"info", run.string()});
  EXPECT_EQ(code, 0) << err;
  EXPECT_EQ(err.find("warning"), std::string::npos) << err;
}

TEST(LayoutVersions, LoadReadsLayout1AsFloat64AndLayout2InItsDeclaredTypes) {
  const CapturedOutputs old = read_outputs(layout_1_run().string());
  ASSERT_TRUE(old.datasets.count("/particles/count"));
  EXPECT_EQ(old.datasets.at("/particles/count").storage, Storage::float64);
  EXPECT_EQ(old.datasets.at("/particles/count").data.size(), 6u);  // samples = 6 in its scene
  EXPECT_EQ(old.attributes.count("/@layout_version"), 0u);

  const fs::path root = fresh_dir("layout-2");
  write_text(root / "scene.toml", std::string(kSceneA) + "[output]\nplots = false\n");
  ASSERT_EQ(run_child({"run", (root / "scene.toml").string(), "--out", (root / "run").string(), "-q"}).first,
            0);
  const CapturedOutputs now = read_outputs((root / "run").string());
  EXPECT_EQ(now.datasets.at("/particles/count").storage, Storage::integer);
  EXPECT_EQ(now.datasets.at("/compare/occupied").storage, Storage::integer);
  EXPECT_EQ(now.datasets.at("/particles/T").storage, Storage::float64);
  EXPECT_EQ(std::get<std::string>(now.attributes.at("/@layout_version")), layout_version_text());
}

// `shockgas upgrade` rewrites nothing (docs/output.md): it checks the result
// as info does and says which layout it holds and that this build reads it;
// for an older layout, how to have the current one. A damaged one is exit 2.
TEST(LayoutVersions, UpgradeSaysWhatIsReadAsItIsAndRewritesNothing) {
  const fs::path old = layout_1_run();
  const std::string said = upgrade_answer(old.string());
  EXPECT_NE(said.find("layout 1.0, which this shockgas reads as it is"), std::string::npos) << said;
  EXPECT_NE(said.find("run its scene again"), std::string::npos) << said;
  EXPECT_EQ(run_child({"info", old.string()}).first, 0);  // as it was

  const fs::path root = fresh_dir("layout-upgrade");
  write_text(root / "scene.toml", std::string(kSceneA) + "[output]\nplots = false\n");
  ASSERT_EQ(run_child({"run", (root / "scene.toml").string(), "--out", (root / "run").string(), "-q"}).first,
            0);
  const std::string now = upgrade_answer((root / "run").string());
  EXPECT_NE(now.find("layout " + layout_version_text() + ", which this shockgas reads as it is"),
            std::string::npos)
      << now;
  EXPECT_EQ(now.find("run its scene again"), std::string::npos) << now;

  {
    std::fstream f(old / "result.h5", std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(3000);
    f.put('\x5a');
  }
  const auto [code, err] = run_child({"upgrade", old.string()});
  EXPECT_EQ(code, 2) << err;
  EXPECT_NE(err.find("damaged"), std::string::npos) << err;
}

}  // namespace
}  // namespace shockgas::app
