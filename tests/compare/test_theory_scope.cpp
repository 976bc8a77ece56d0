// Where each law holds (shockgas/compare/theory_scope.hpp), on scenes whose
// physics is known: a gas of random velocities, a sine wave, an N-wave, a
// Riemann problem, three particles.
#include <gtest/gtest.h>

#include <numbers>

#include "shockgas/compare/theory.hpp"
#include "shockgas/compare/theory_scope.hpp"

namespace shockgas::compare {
namespace {

SceneShape gas(double r, std::size_t N = 20000) {
  SceneShape s;
  s.N = N, s.r = r, s.random_velocities = s.uniform_density = true;
  return s;
}

SceneShape wave(double t_star, double pulse_fraction, bool particles) {
  SceneShape s;
  s.breaking_time = t_star, s.pulse_fraction = pulse_fraction, s.uniform_density = true;
  if (particles) s.N = 2000, s.r = 0;
  return s;
}

// r = 0.5, t_stick = 8: the default scene's window [t_end / 100, t_end] starts
// past 10 t_stick and stays; no homogeneous-cooling regime between 1/eps = 4 and 8.
TEST(TheoryScope, AGasAtHalfRestitutionCoolsAsTheStickyGasOnItsWindow) {
  SceneShape s = gas(0.5);
  s.fit_window = 100;
  const Scope cooling = scope(Law::sticky_cooling, s, 1e4);
  ASSERT_TRUE(cooling.holds) << cooling.reason;
  EXPECT_EQ(cooling.t_min, 100);
  EXPECT_EQ(cooling.t_max, 1e4);
  EXPECT_FALSE(scope(Law::crossovers, s, 1e4).holds);
  for (Law law : {Law::velocity_scaling, Law::shock_count, Law::clusters_are_shocks, Law::ramp_slope})
    EXPECT_TRUE(scope(law, s, 1e4).holds) << declaration(law).id;
  for (Law law : {Law::breaking, Law::n_wave_decay, Law::sawtooth_decay, Law::lobe_areas})
    EXPECT_FALSE(scope(law, s, 1e4).holds) << declaration(law).id;
}

// r = 0.99: t_stick = eps^(-3/2) = 2828, so at t = 10^4 the gas is not yet
// sticky (10 t_stick = 28284) while its crossovers are far apart (eps^(-1/2) = 14).
// At r = 0.97 the window starts a decade after t_stick, not at t_end / fit_window.
TEST(TheoryScope, TheStickyLawStartsADecadeAfterTStick) {
  EXPECT_FALSE(scope(Law::sticky_cooling, gas(0.99), 1e4).holds);
  EXPECT_TRUE(scope(Law::crossovers, gas(0.99), 1e4).holds);
  const Scope late = scope(Law::sticky_cooling, gas(0.97), 2e4);
  ASSERT_TRUE(late.holds);
  EXPECT_DOUBLE_EQ(late.t_min, 10 * sticking_time(0.97));
  EXPECT_FALSE(scope(Law::sticky_cooling, gas(0.5, 3), 1e4).holds);  // three particles
}

// A sine of period 1 breaks at t* = 1/(2 pi): its breaking holds, but up to
// t = 0.5 = 3.1 t* neither its sawtooth's 1/t ramps nor its decay do; by t = 20
// the decay holds from 10 t*; an N-wave's laws never apply to it.
TEST(TheoryScope, ASineBreaksButIsNoSawtoothBeforeTenTimesItsBreakingTime) {
  const double t_star = 1 / (2 * std::numbers::pi);
  const SceneShape sine = wave(t_star, 1.0, true);
  EXPECT_TRUE(scope(Law::breaking, sine, 0.5).holds);
  EXPECT_TRUE(scope(Law::clusters_are_shocks, sine, 0.5).holds);  // r = 0, uniform density
  for (Law law : {Law::sticky_cooling, Law::crossovers, Law::velocity_scaling, Law::shock_count,
                  Law::ramp_slope, Law::sawtooth_decay, Law::n_wave_decay, Law::lobe_areas})
    EXPECT_FALSE(scope(law, sine, 0.5).holds) << declaration(law).id;
  const Scope decay = scope(Law::sawtooth_decay, sine, 20);
  ASSERT_TRUE(decay.holds);
  EXPECT_DOUBLE_EQ(decay.t_min, 2.0);  // t_end / fit_window = 2 > 10 t* = 1.59
  EXPECT_FALSE(scope(Law::n_wave_decay, sine, 20).holds);
  EXPECT_EQ(theory_note(Law::sawtooth_decay, sine, 0.5).rfind("no theory for this scene", 0), 0u);
  EXPECT_EQ(theory_note(Law::sawtooth_decay, sine, 20),
            "theory `sawtooth_decay` (Whitham ch. 2): exponent -1");
}

// T(t) is never fitted across a crossover: the sticky law's window where it
// holds; else [t_end / fit_window, t_end] from no earlier than a decade after
// the last crossover, whatever fit_window says; none where that decade is past
// t_end (the sine to t = 0.5, t* = 0.159; r = 0.9 to t = 600, t_stick = 89.4),
// with the reason.
TEST(TheoryScope, TheCoolingFitNeverSpansACrossover) {
  const Scope sticky = cooling_fit_scope(gas(0.5), 1e4);
  EXPECT_TRUE(sticky.holds);
  EXPECT_EQ(sticky.t_min, 1e3);  // t_end / fit_window = 10^3 > 10 t_stick = 80
  const double t_star = 1 / (2 * std::numbers::pi);
  const Scope sine = cooling_fit_scope(wave(t_star, 1.0, true), 0.5);
  EXPECT_FALSE(sine.holds);
  EXPECT_NE(sine.reason.find("the crossover the breaking time t* = 0.159 (1.59) is past t_end = 0.5"),
            std::string::npos)
      << sine.reason;
  const Scope later = cooling_fit_scope(wave(t_star, 1.0, true), 20);
  ASSERT_TRUE(later.holds) << later.reason;
  EXPECT_EQ(later.t_min, 2.0);  // t_end / fit_window = 2 > 10 t* = 1.59
  SceneShape wide = wave(t_star, 1.0, true);
  wide.fit_window = 100;  // [0.2, 20] would start before 10 t*
  const Scope from_decade = cooling_fit_scope(wide, 20);
  ASSERT_TRUE(from_decade.holds) << from_decade.reason;
  EXPECT_DOUBLE_EQ(from_decade.t_min, 10 * t_star);
  for (const double fit_window : {2.0, 10.0, 100.0}) {  // r = 0.9 to t = 600 or 300: 10 t_stick = 894
    SceneShape gas_09 = gas(0.9);
    gas_09.fit_window = fit_window;
    for (const double t_end : {300.0, 600.0}) {
      const Scope short_gas = cooling_fit_scope(gas_09, t_end);
      EXPECT_FALSE(short_gas.holds) << fit_window << " " << t_end;
      EXPECT_NE(short_gas.reason.find("t_stick ~ eps^(-3/2) = 89.4 (894) is past t_end"), std::string::npos)
          << short_gas.reason;
    }
  }
  // r = 0.99 to t = 1000: t_stick = 2828 is past t_end, t_dissip = 200 is not, and a decade after it
  // (2000) is past t_end too, whatever fit_window says (a fit on [1, 1000] had averaged the elastic
  // regime and the cooling one to -0.49)
  for (const double fit_window : {2.0, 10.0, 1000.0}) {
    SceneShape nearly_elastic = gas(0.99);
    nearly_elastic.fit_window = fit_window;
    const Scope none = cooling_fit_scope(nearly_elastic, 1000);
    EXPECT_FALSE(none.holds) << fit_window;
    EXPECT_NE(none.reason.find("t_dissip ~ 1/eps = 200 (2e+03) is past t_end"), std::string::npos)
        << none.reason;
  }
  // 400 particles: the sticky law ends at N^(3/2) / 10 = 800 < 10 t_stick = 894, so it holds nowhere;
  // T is still fitted, after 10 t_stick.
  SceneShape few = gas(0.9, 400);
  few.fit_window = 2;
  EXPECT_FALSE(scope(Law::sticky_cooling, few, 2000).holds);
  const Scope after = cooling_fit_scope(few, 2000);
  ASSERT_TRUE(after.holds) << after.reason;
  EXPECT_EQ(after.t_min, 1000);
  few.fit_window = 10;
  const Scope later_start = cooling_fit_scope(few, 2000);
  ASSERT_TRUE(later_start.holds) << later_start.reason;
  EXPECT_DOUBLE_EQ(later_start.t_min, 10 * sticking_time(0.9));
}

// An isolated pulse keeps its lobes and decays as t^(-1/2); a jump (a Riemann
// problem, t* = 0) has no breaking and no decay law.
TEST(TheoryScope, AnIsolatedPulseIsAnNWaveAndAJumpNoWaveAtAll) {
  const SceneShape pulse = wave(0.008, 0.05, true);
  EXPECT_TRUE(scope(Law::n_wave_decay, pulse, 4).holds);
  EXPECT_TRUE(scope(Law::lobe_areas, pulse, 4).holds);
  EXPECT_FALSE(scope(Law::sawtooth_decay, pulse, 4).holds);
  const SceneShape jump = wave(0.0, 0.9, false);
  for (Law law : {Law::breaking, Law::n_wave_decay, Law::sawtooth_decay, Law::lobe_areas, Law::ramp_slope,
                  Law::clusters_are_shocks})
    EXPECT_FALSE(scope(law, jump, 0.2).holds) << declaration(law).id;
}

TEST(TheoryScope, EveryLawIsDeclaredOnceInTheOrderOfTheEnum) {
  const auto& all = theory_declarations();
  for (std::size_t i = 0; i < all.size(); ++i) EXPECT_EQ(static_cast<std::size_t>(all[i].law), i);
  EXPECT_EQ(all.back().law, Law::lobe_areas);
}

}  // namespace
}  // namespace shockgas::compare
