#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>

#include "reference_table.hpp"
#include "shockgas/compare/airy.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::compare {
namespace {

using cplx = std::complex<double>;
constexpr double kEps = 2.220446049250313e-16;

// The size of Ai near z: |Ai| + |Ai'| / |z|^(1/2) (Ai' ~ z^(1/2) Ai), which does
// not vanish at the zeros of Ai or Ai', where only absolute accuracy is possible.
double envelope(cplx z, AiryPair w) {
  return std::abs(w.ai) + std::abs(w.aip) / std::sqrt(std::max(1.0, std::abs(z)));
}

TEST(Airy, AgreesWithScipyOnRingsAcrossEveryMethod) {
  // Rings |z| = 0.3 ... 40 over all arguments (scripts/reference/chernoff_reference.py):
  // Maclaurin, both path directions, the expansion and the connection formula,
  // and both sides of each switch. Tolerance: a path of up to ~30 Taylor steps
  // of a few eps each (airy.cpp), times 1 + |zeta| for the conditioning of the
  // phase exp(-zeta) itself: 100 eps (1 + |zeta|) of the envelope. Measured: 37.
  const auto rows = testing::read_reference_table("airy_reference.csv");
  ASSERT_GT(rows.size(), 250u);
  for (const auto& r : rows) {
    const cplx z(r[0], r[1]);
    const AiryPair ref{cplx(r[2], r[3]), cplx(r[4], r[5])}, w = airy(z);
    const double tolerance = 100 * kEps * (1 + std::abs(airy_zeta(z))) * envelope(z, ref);
    const double scale = std::sqrt(std::max(1.0, std::abs(z)));
    EXPECT_LE(std::abs(w.ai - ref.ai), tolerance) << "Ai at z = " << z;
    EXPECT_LE(std::abs(w.aip - ref.aip) / scale, tolerance) << "Ai' at z = " << z;
  }
}

TEST(Airy, ScaledIsExpZetaTimesAi) {
  for (const cplx z : {cplx(0.5, 0.2), cplx(3, 4), cplx(-2, 1), cplx(12, -5), cplx(-15, 3)}) {
    const AiryPair w = airy(z), s = airy_scaled(z);
    const cplx e = std::exp(airy_zeta(z));
    EXPECT_LE(std::abs(s.ai - e * w.ai), 1e-13 * std::abs(s.ai)) << z;
    EXPECT_LE(std::abs(s.aip - e * w.aip), 1e-13 * std::abs(s.aip)) << z;
  }
  // Far out, where Ai(100) ~ 1e-291 nearly underflows: e^zeta Ai(z) ~ (1 - u_1/zeta + u_2/zeta^2)
  // / (2 sqrt(pi) z^(1/4)), zeta = 2000/3; the next term u_3/zeta^3 = 1.3e-10 relative.
  const double zeta = 2000.0 / 3, u1 = 5.0 / 72, u2 = 385.0 / 10368;
  const double expected = (1 - u1 / zeta + u2 / (zeta * zeta)) / (2 * std::sqrt(std::numbers::pi * 10.0));
  EXPECT_NEAR(airy_scaled(100.0).ai.real(), expected, 2e-10 * expected);
}

TEST(Airy, TaylorStepsFollowTheOde) {
  // Stepping from 0 to 2 + 3i in 50 steps lands on the direct evaluation.
  AiryPair w = airy(0.0);
  const cplx target(2, 3), h = target / 50.0;
  for (int k = 0; k < 50; ++k) w = airy_step(static_cast<double>(k) * h, w, h);
  const AiryPair direct = airy(target);
  EXPECT_LE(std::abs(w.ai - direct.ai), 1e-13 * std::abs(direct.ai));
  EXPECT_LE(std::abs(w.aip - direct.aip), 1e-13 * std::abs(direct.aip));
}

TEST(Airy, ZerosMatchTheTables) {
  // SciPy's scipy.special.ai_zeros (1.10), which agree with DLMF Table 9.9.1 to
  // its 10 decimals; a few eps relative.
  EXPECT_NEAR(airy_ai_zero(1).a, -2.3381074104597674, 4 * kEps * 2.34);
  EXPECT_NEAR(airy_ai_zero(1).aip, 0.7012108227206915, 8 * kEps);
  EXPECT_NEAR(airy_ai_zero(2).a, -4.08794944413097, 4 * kEps * 4.09);
  EXPECT_NEAR(airy_ai_zero(2).aip, -0.8031113696548628, 8 * kEps);
  EXPECT_NEAR(airy_ai_zero(10).a, -12.828776752865757, 4 * kEps * 12.8);
  // Ai vanishes there to the accuracy of the first test (|a_500| = 176, |zeta| = 1560).
  for (int k : {1, 5, 50, 500}) {
    const double a = airy_ai_zero(k).a;
    const double tolerance = 100 * kEps * (1 + std::abs(airy_zeta(a))) * envelope(a, airy(a));
    EXPECT_LE(std::abs(airy(a).ai), tolerance) << k;
  }
  EXPECT_THROW(airy_ai_zero(0), InputError);
}

}  // namespace
}  // namespace shockgas::compare
