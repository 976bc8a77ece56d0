#pragma once
// The set-up of the tests that replace one run by another: alpha's complete
// results in root/D, made by the command, and beta ready to run over them.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "child_run.hpp"
#include "run_dir_checks.hpp"

namespace shockgas::app::testing {

struct TwoRuns {
  fs::path root, a, b, out, script;  // script: fake_plot_script() of root
};

// plot_seconds: how long the test's plotting script sleeps between its two pictures.
inline TwoRuns alpha_done(const fs::path& root, double plot_seconds = 0) {
  TwoRuns s;
  s.root = root;
  s.a = root / "alpha.toml";
  s.b = root / "beta.toml";
  s.out = root / "D";
  write_text(s.a, kSceneA);
  write_text(s.b, kSceneB);
  s.script = fake_plot_script(root, plot_seconds);
  const auto [code, err] = run_child({"run", s.a.string(), "--out", s.out.string(), "-q", "--no-plots"});
  EXPECT_EQ(code, 0) << err;
  return s;
}

}  // namespace shockgas::app::testing
