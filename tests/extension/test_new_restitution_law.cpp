// A restitution law registered from outside (smooth_restitution.hpp) runs
// through the engine like the built-in rule: each bounce keeps the momentum and
// maps the approach speed g to -r(g) g, a scene names the law in
// particles.restitution_law, and its constant limit gives the built-in rule's
// run to the bit. Its own suite in the extension executable: the registration
// is global to the process.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "particles/engine_fixtures.hpp"
#include "process_temp_path.hpp"
#include "shockgas/app/cli/command.hpp"
#include "shockgas/core/bodies.hpp"
#include "shockgas/core/error.hpp"
#include "shockgas/core/initial_condition.hpp"
#include "shockgas/particles/simulate.hpp"
#include "smooth_restitution.hpp"

namespace shockgas::extension {
namespace {

namespace fs = std::filesystem;
using particles::ParticleParams;
using particles::detail::EventEngine;

constexpr double kG0 = 0.5;                         // the smooth law's speed scale [length/time]
constexpr char kSmooth[] = "test_smooth";           // g0 = kG0
constexpr char kConstantLimit[] = "test_smooth_0";  // g0 = 0: the constant r
constexpr char kAboveOne[] = "test_above_one";      // r(g) = 1.5: not a restitution
constexpr double kEps = std::numeric_limits<double>::epsilon();

class NewRestitutionLaw : public testing::Test {
 protected:
  static void SetUpTestSuite() {
    particles::register_restitution_law(smooth_restitution_law(kSmooth, kG0));
    particles::register_restitution_law(smooth_restitution_law(kConstantLimit, 0.0));
    particles::RestitutionLawInfo above_one{kAboveOne, "r(g) = 1.5", [](const ParticleParams&) {
                                              return particles::RestitutionLaw([](double) { return 1.5; });
                                            }};
    particles::register_restitution_law(above_one);
  }
};

// Bounces with a threshold on a ring (no collapse), under the law `law`.
ParticleParams gas(const std::string& law, double t_end) {
  ParticleParams p;
  p.r = 0.5;
  p.delta = 0.05;
  p.restitution_law = law;
  p.t_end = t_end;
  p.samples = 5;
  p.clusters = false;
  return p;
}

Bodies lattice_gas(std::size_t n, std::uint64_t seed) {
  InitialParams ip;
  ip.N = n;
  ip.seed = seed;
  return make_initial_bodies(ip);
}

// The engine's bodies: (v, m) by index.
template <bool Linked>
std::vector<std::pair<double, double>> velocities_and_masses(const EventEngine<Linked>& e) {
  std::vector<std::pair<double, double>> out(e.size());
  e.for_each_body(e.now(), [&](std::size_t i, double, double v, double m) { out[i] = {v, m}; });
  return out;
}

// The slot of the engine's next collision (the smallest contact time).
template <bool Linked>
std::size_t next_slot(const EventEngine<Linked>& e) {
  std::size_t next = 0;
  for (std::size_t i = 1; i < e.size(); ++i)
    if (e.slot_time(i) < e.slot_time(next)) next = i;
  return next;
}

// Runs the engine collision by collision and holds each against the law: the
// relative velocity after it is -r(g) g (r = 1 below delta) and the momentum of
// the pair is kept. Returns the r(g) of the inelastic collisions.
template <bool Linked>
std::vector<double> check_each_collision(EventEngine<Linked>& e, const ParticleParams& p, int collisions) {
  e.use_global_queue();
  std::vector<double> inelastic;
  for (int k = 0; k < collisions; ++k) {
    const std::size_t i = next_slot(e), j = (i + 1) % e.size();  // no merges: the right neighbour
    const auto before = velocities_and_masses(e);
    const std::uint64_t done = e.collisions();
    e.run_until(e.slot_time(i), [](double, std::uint64_t) { return true; });
    EXPECT_EQ(e.collisions(), done + 1) << "one collision at a time (seeded data without ties)";
    const auto after = velocities_and_masses(e);
    const auto [v, mL] = before[i];
    const auto [u, mR] = before[j];
    const double g = v - u;
    const double r = g < p.delta ? 1.0 : smooth_restitution(p.r, kG0, g);
    if (g >= p.delta) inelastic.push_back(r);
    // v' and u' are a few roundings (of terms up to 2 g, g <= |v| + |u|) from
    // their exact values, each rounding at most eps/2 of 3 (|v| + |u|): 16 eps
    // (|v| + |u|) bounds the error of v' - u' and, times the mass, of the momentum.
    const double bound = 16 * kEps * (std::abs(v) + std::abs(u));
    EXPECT_NEAR(after[i].first - after[j].first, -r * g, bound) << "collision " << k << ", g = " << g;
    EXPECT_NEAR(mL * after[i].first + mR * after[j].first, mL * v + mR * u, (mL + mR) * bound)
        << "collision " << k;
  }
  return inelastic;
}

// The r(g) seen span the law's range (g from delta to ~2: r from 0.95 to 0.51),
// so the law acted, not a constant.
void expect_a_range_of_restitutions(const std::vector<double>& r) {
  ASSERT_GT(r.size(), 100u);
  const auto [lo, hi] = std::minmax_element(r.begin(), r.end());
  EXPECT_GT(*hi - *lo, 0.2) << *lo << " .. " << *hi;
}

TEST_F(NewRestitutionLaw, EachEqualMassBounceMapsGToMinusRofG) {
  const ParticleParams p = gas(kSmooth, 1);
  auto e = particles::detail::engine_of<false>(lattice_gas(64, 7), true, particles::collision_rule(p));
  expect_a_range_of_restitutions(check_each_collision(e, p, 3000));
  EXPECT_GT(e.count(particles::CollisionKind::elastic), 100u);  // and sub-threshold ones
}

TEST_F(NewRestitutionLaw, EachBounceOfUnequalMassesMapsGToMinusRofG) {
  const ParticleParams p = gas(kSmooth, 1);
  const Bodies b = lattice_gas(64, 8);
  EventEngine<true> e(b.size(), static_cast<double>(b.size()), true, particles::collision_rule(p),
                      [&](std::size_t first, std::size_t count, double* x, double* v, double* m) {
                        std::copy_n(b.x.begin() + first, count, x);
                        std::copy_n(b.v.begin() + first, count, v);
                        for (std::size_t k = 0; k < count; ++k) m[k] = 1.0 + 0.5 * ((first + k) % 3);
                      });
  expect_a_range_of_restitutions(check_each_collision(e, p, 3000));
}

// The law's constant limit against the built-in rule, both on the global queue
// (a law runs there: the windows' step is the constant rule's): every number of
// the run equal to the bit.
TEST_F(NewRestitutionLaw, ItsConstantLimitIsTheBuiltInRuleToTheBit) {
  const Bodies b = lattice_gas(4096, 9);
  ParticleParams builtin = gas(particles::kConstantRestitution, 200);
  builtin.schedule = particles::Schedule::global;
  const particles::RunResult law = particles::simulate(b, 4096.0, gas(kConstantLimit, 200));
  const particles::RunResult rule = particles::simulate(b, 4096.0, builtin);
  ASSERT_GT(rule.collisions, 100000u);  // a run long enough that one different bit would spread
  EXPECT_EQ(law.collisions, rule.collisions);
  EXPECT_EQ(law.series.T, rule.series.T);
  EXPECT_EQ(law.series.inelastic, rule.series.inelastic);
  EXPECT_EQ(law.series.dissipated, rule.series.dissipated);
  EXPECT_EQ(law.final_state.x, rule.final_state.x);
  EXPECT_EQ(law.final_state.v, rule.final_state.v);
  EXPECT_EQ(law.schedule.order, "global");
  EXPECT_NE(law.schedule.why_global.find("restitution law"), std::string::npos) << law.schedule.why_global;
}

TEST_F(NewRestitutionLaw, TheEnergyLostIsTheEnergyDissipated) {
  const Bodies b = lattice_gas(2000, 10);
  const particles::RunResult out = particles::simulate(b, 2000.0, gas(kSmooth, 50));
  ASSERT_GT(out.series.inelastic.back(), 10000.0);
  // Rounding per collision ~1e-16 relative (tests/particles Engine.EnergyBalanceWithDissipation).
  EXPECT_NEAR(kinetic_energy(out.final_state) + out.series.dissipated.back(), kinetic_energy(b),
              1e-11 * kinetic_energy(b));
}

TEST_F(NewRestitutionLaw, ARestitutionAboveOneStopsTheRun) {
  try {
    particles::simulate(lattice_gas(64, 11), 64.0, gas(kAboveOne, 10));
    FAIL() << "r(g) = 1.5 accepted";
  } catch (const RunError& e) {
    EXPECT_NE(std::string(e.what()).find(kAboveOne), std::string::npos) << e.what();
  }
}

// Runs the command in this process; what it said on stderr into *said.
int run(std::vector<std::string> args, std::string* said = nullptr) {
  args.insert(args.begin(), "shockgas");
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  if (said) ::testing::internal::CaptureStderr();
  const int code = app::run_command(static_cast<int>(argv.size()), argv.data());
  if (said) *said = ::testing::internal::GetCapturedStderr();
  return code;
}

fs::path write_scene(const fs::path& dir) {
  fs::create_directories(dir);
  fs::path path = dir / "scene.toml";
  std::ofstream(path) << "[initial]\nN = 2048\n[particles]\nr = 0.5\ndelta = 0.05\nt_end = 20\n"
                      << "[output]\nplots = false\n";
  return path;
}

TEST_F(NewRestitutionLaw, AScenePicksItByName) {
  const fs::path dir = testing_support::process_temp_path("shockgas-test-extension-", "law");
  fs::remove_all(dir);
  const fs::path scene = write_scene(dir);
  const std::string law = std::string("particles.restitution_law=") + kSmooth;
  ASSERT_EQ(run({"run", scene.string(), "--set", law, "--out", (dir / "out").string(), "-q"}), 0);
  std::ifstream in(dir / "out" / "summary.json");
  const nlohmann::json summary = nlohmann::json::parse(in);
  EXPECT_EQ(summary["particles"]["schedule"], "global");
  const std::string note = summary["particles"]["schedule_note"];
  EXPECT_NE(note.find("restitution law"), std::string::npos) << note;

  std::string said;
  const std::string unknown = "particles.restitution_law=test_smoth";
  EXPECT_EQ(run({"run", scene.string(), "--set", unknown, "--out", (dir / "bad").string(), "-q"}, &said), 2);
  EXPECT_NE(said.find(kSmooth), std::string::npos) << said;  // the registered names are listed
  EXPECT_FALSE(fs::exists(dir / "bad"));
}

}  // namespace
}  // namespace shockgas::extension
