// The Courant bound of MUSCL-Hancock depends on the limiter: refused above it
// unless continuum.allow_unstable (bounds in godunov_scheme.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "shockgas/continuum/godunov.hpp"
#include "shockgas/continuum/godunov_scheme.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::continuum {
namespace {

InitialField sine_wave() {
  InitialField f;
  f.length = 1.0;
  f.v0 = [](double x) { return 0.5 + std::sin(2 * M_PI * x); };
  f.rho0 = [](double) { return 1.0; };
  return f;
}

bool refused(const std::string& limiter, double cfl, bool allow_unstable = false) {
  ContinuumParams p;
  p.cells = 64;
  p.limiter = parse_enum<Limiter>(limiter, "continuum.limiter");
  p.cfl = cfl;
  p.allow_unstable = allow_unstable;
  try {
    solve_godunov(sine_wave(), p, 0.05, 2);
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "continuum.cfl");
    return true;
  }
  return false;
}

TEST(GodunovCfl, MusclHancockBoundFollowsTheLimiter) {
  EXPECT_FALSE(refused("minmod", kMusclHancockCflMax));
  EXPECT_FALSE(refused("vanleer", kMusclHancockVanLeerCflMax));
  EXPECT_TRUE(refused("vanleer", kMusclHancockVanLeerCflMax + 0.01));
  EXPECT_FALSE(refused("mc", kMusclHancockMcCflMax));
  EXPECT_TRUE(refused("mc", kMusclHancockMcCflMax + 0.01));
}

TEST(GodunovCfl, AllowUnstableRunsBeyondTheBound) { EXPECT_FALSE(refused("mc", 0.95, true)); }

}  // namespace
}  // namespace shockgas::continuum
