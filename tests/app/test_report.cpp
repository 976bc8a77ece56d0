// The numbers of a run as a physicist reads them: report.md says what was asked
// and what was run (the overrides, the parameters used), and the L1 distances
// of the summary are normalised (per unit length, relative to the reference).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "run_command.hpp"
#include "shockgas/app/output/hdf5_file.hpp"

namespace shockgas::app {
namespace {

namespace fs = std::filesystem;

using testing_support::run;

std::string read_text(const fs::path& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// Runs `scene` with `overrides` into a fresh directory; returns the output directory.
fs::path run_scene(const std::string& name, const std::string& scene,
                   const std::vector<std::string>& overrides) {
  const fs::path dir = testing_support::fresh_process_directory("shockgas-test-report-", name);
  std::ofstream(dir / "scene.toml") << scene;
  std::vector<std::string> args = {"run", (dir / "scene.toml").string(), "--out", (dir / "out").string(),
                                   "-q"};
  for (const auto& o : overrides) args.insert(args.end(), {"--set", o});
  EXPECT_EQ(run(args), 0);
  return dir / "out";
}

// The gas of 4096 lattice particles and two continuum solvers on L = 4096: the
// size at which the old, unnormalised density distance read 4980.
const char* kWhiteNoise =
    "[scene]\ndescription = \"Burgers turbulence of 20000 particles\"\n"
    "[initial]\nN = 20000\nseed = 3\n[continuum]\nsolvers = [\"hopf_lax\", \"godunov\"]\ncells = 4096\n"
    "t_end = 100\n[output]\nplots = false\n";

// After --set initial.N=4096 the description (the author's words) still says
// 20000: report.md keeps it as written and states the run as made beside it.
TEST(Report, StatesTheOverridesAndTheParametersUsed) {
  const fs::path out = run_scene("overrides", kWhiteNoise, {"initial.N=4096"});
  const std::string report = read_text(out / "report.md");
  EXPECT_NE(report.find("Burgers turbulence of 20000 particles"), std::string::npos) << report;
  EXPECT_NE(report.find("`--set initial.N=4096`"), std::string::npos) << report;
  EXPECT_NE(report.find("`initial.N = 4096` (override)"), std::string::npos) << report;
  EXPECT_NE(report.find("`continuum.cells = 4096`"), std::string::npos) << report;
  EXPECT_EQ(report.find("initial.N = 20000"), std::string::npos) << report;
  const fs::path plain = run_scene("plain", kWhiteNoise, {"continuum.t_end=10"});
  EXPECT_NE(read_text(plain / "report.md").find("`continuum.t_end = 10` (override)"), std::string::npos);
}

double mean_abs_difference(const std::vector<double>& a, const std::vector<double>& b) {
  double s = 0;
  for (std::size_t i = 0; i < a.size(); ++i) s += std::abs(a[i] - b[i]);
  return s / static_cast<double>(a.size());
}

// The summary's distances recomputed from the fields in result.h5: per unit
// length = the mean over cells of |difference| (uniform grid), relative = the
// sum of |difference| over the sum of |reference - its mean| (v) or of the
// reference (rho, the mass). They agree to rounding (1e-12 relative).
TEST(Report, L1DistancesArePerUnitLengthAndRelative) {
  const fs::path out = run_scene("l1", kWhiteNoise, {"initial.N=4096"});
  const auto summary = nlohmann::json::parse(read_text(out / "summary.json"));
  const auto& g = summary["continuum"]["godunov"];
  const Hdf5File h5 = Hdf5File::open((out / "result.h5").string());
  const auto v = h5.read("/continuum/godunov/v"), v_exact = h5.read("/continuum/hopf_lax/v");
  const auto rho = h5.read("/continuum/godunov/rho"), rho_exact = h5.read("/continuum/hopf_lax/rho");
  ASSERT_EQ(v.size(), 4096u);
  double v_mean = 0, mass = 0;
  for (std::size_t i = 0; i < v.size(); ++i) v_mean += v_exact[i] / 4096.0, mass += rho_exact[i] / 4096.0;
  std::vector<double> v_spread(v.size(), v_mean), none(v.size(), 0.0);
  EXPECT_NEAR(g["l1_v"].get<double>(), mean_abs_difference(v, v_exact),
              1e-12 * mean_abs_difference(v, v_exact));
  EXPECT_NEAR(g["l1_v_relative"].get<double>(),
              mean_abs_difference(v, v_exact) / mean_abs_difference(v_exact, v_spread), 1e-12);
  EXPECT_NEAR(g["l1_rho"].get<double>(), mean_abs_difference(rho, rho_exact), 1e-12);
  EXPECT_NEAR(g["l1_rho_relative"].get<double>(), mean_abs_difference(rho, rho_exact) / mass, 1e-12);
  // Two densities of the same mass are at most 2 apart relative to it (the old
  // unnormalised number was 4980, above the mass 4096 itself).
  EXPECT_LE(g["l1_rho_relative"].get<double>(), 2.0);
  EXPECT_NEAR(mass, 1.0, 1e-12);  // unit mean density: per length = relative for rho here
  EXPECT_FALSE(summary["continuum"]["hopf_lax"].contains("l1_v"));  // the reference itself
}

// Found from outside: on white noise the distances to hopf_lax levelled off
// as the cells grew (godunov2 0.103, 0.091, 0.082 of the variation at 4096,
// 8192, 16384 cells, N = 4096): hopf_lax is exact for the point masses, the
// grids start from cell data. The report says so where the start is the
// particles, and not where it is v0(x), whose exact solution the grids share.
TEST(Report, DistancesFromAParticleStartSayWhatTheyMeasure) {
  const std::string caveat = "The exact solution here is that of the particles' own start";
  const std::string particles =
      read_text(run_scene("particle-start", kWhiteNoise, {"initial.N=4096"}) / "report.md");
  EXPECT_NE(particles.find("L1 distance to the exact solution"), std::string::npos) << particles;
  EXPECT_NE(particles.find(caveat), std::string::npos) << particles;
  const char* sine =
      "[initial]\nvelocities = \"expression\"\nv0 = \"0.5 + sin(2*pi*x)\"\ndomain = 1.0\n"
      "[continuum]\nsolvers = [\"hopf_lax\", \"godunov\"]\ncells = 256\nt_end = 0.5\n[output]\nplots = "
      "false\n";
  const std::string field = read_text(run_scene("field-start", sine, {}) / "report.md");
  EXPECT_NE(field.find("L1 distance to the exact solution"), std::string::npos) << field;
  EXPECT_EQ(field.find(caveat), std::string::npos) << field;
}

// A run whose particles stop early is held to the time its data end (found
// from outside: a run that stopped at t = 1.8 of 2000 kept theory.shock_count
// and ramp_slope as holding on [80, 2000], and its report named them beside
// slopes of 0.16 and 0.00015, with an "exact" white-noise count of 420 where the
// exact solver found 1033). Stopped here by particles.max_collisions at t ~ 30,
// before 10 t_stick = 80; the same scene run to its end holds them.
TEST(Report, AnEarlyStopIsHeldToTheTimeItsDataEnd) {
  const char* gas =
      "[initial]\nN = 4096\nseed = 9999\n[particles]\nr = 0.5\ndelta = 3e-3\nt_end = 2000\nsamples = 20\n"
      "[continuum]\nsolvers = [\"hopf_lax\"]\ncells = 4096\n[compare]\n[output]\nplots = false\n";
  const fs::path stopped = run_scene("early-stop", gas, {"particles.max_collisions=200000"});
  const auto s = nlohmann::json::parse(read_text(stopped / "summary.json"));
  ASSERT_EQ(s["particles"]["stop"], "event_limit");
  const double t_stop = s["particles"]["stop_time"].get<double>();
  ASSERT_LT(t_stop, 80.0);
  for (const char* law : {"shock_count", "clusters_are_shocks", "ramp_slope", "velocity_scaling"}) {
    EXPECT_FALSE(s["theory"][law]["holds"].get<bool>()) << law;
    EXPECT_NE(s["theory"][law]["why"].get<std::string>().find("before t = "), std::string::npos) << law;
  }
  const std::string report = read_text(stopped / "report.md");
  EXPECT_EQ(report.find("(theory `shock_count`"), std::string::npos) << report;
  EXPECT_EQ(report.find("exact for this white noise"), std::string::npos) << report;

  const auto whole =
      nlohmann::json::parse(read_text(run_scene("early-stop-control", gas, {}) / "summary.json"));
  ASSERT_EQ(whole["particles"]["stop"], "completed");
  for (const char* law : {"shock_count", "clusters_are_shocks", "ramp_slope", "velocity_scaling"})
    EXPECT_TRUE(whole["theory"][law]["holds"].get<bool>()) << law;
}

}  // namespace
}  // namespace shockgas::app
