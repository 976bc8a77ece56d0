#pragma once
// The exact sticky gas from the same starts as a gas ensemble: the hull at
// r = 0 (particles/hull_model.hpp), realization by realization, sampled at the
// gas's times. A reference for the gas's cooling exponent that shares its
// starts, so that what the starts give both (the spread of the exponent from
// one start to another, large for a few thousand clusters) cancels in their
// difference (jackknife_paired_T_exponents): what is left is the gas's
// dynamics. The default scene's 2 realizations give -0.6972 on [10^2, 10^4]
// where the sticky gas from their starts gives -0.6974 (the exponent spreads
// by 0.046 from one start to another there; 64 starts give -0.673 together,
// docs/validate.md).
//
// Run only where it is cheap beside the gas: the hull of at most
// kSameStartsBodies bodies over all realizations, one realization at a time
// (measured 0.07-0.14 s per 10^6 bodies with 40 samples, 13.5 bytes per body).
#include <cstddef>
#include <vector>

#include "shockgas/core/initial_condition.hpp"
#include "shockgas/particles/params.hpp"

namespace shockgas::compare {

inline constexpr double kSameStartsBodies = 1e6;

// Whether the reference is made for a gas of these parameters and N
// particles: r > 0 (at r = 0 the gas is the sticky gas), 2 or more
// realizations (the paired jackknife), and N x realizations <= kSameStartsBodies.
bool same_starts_apply(const particles::ParticleParams& gas, std::size_t N);

// T(t) of the sticky gas from realization k's start, k = 0 .. realizations - 1,
// at the gas's sample times (particles.t_end, particles.samples).
std::vector<std::vector<double>> sticky_T_rows(const InitialCondition& initial,
                                               const particles::ParticleParams& gas);

}  // namespace shockgas::compare
