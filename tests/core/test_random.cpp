#include <gtest/gtest.h>

#include "shockgas/core/random.hpp"

namespace shockgas {

TEST(Random, SameSeedSameStream) {
  Rng a(42), b(42);
  for (int i = 0; i < 100; ++i) EXPECT_EQ(a.next(), b.next());
}

TEST(Random, RealizationSeedsDiffer) {
  EXPECT_NE(realization_seed(1, 0), realization_seed(1, 1));
  EXPECT_NE(realization_seed(1, 0), realization_seed(2, 0));
}

// Mean and variance of U[0,1): 1/2 and 1/12; with n = 1e6 samples the standard
// error of the mean is sqrt(1/12/n) ~ 2.9e-4, so 5 sigma is 1.5e-3.
TEST(Random, UniformMoments) {
  Rng rng(7);
  const int n = 1000000;
  double s = 0, s2 = 0;
  for (int i = 0; i < n; ++i) {
    const double u = rng.uniform();
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
    s += u;
    s2 += u * u;
  }
  EXPECT_NEAR(s / n, 0.5, 1.5e-3);
  EXPECT_NEAR(s2 / n - (s / n) * (s / n), 1.0 / 12, 1e-3);
}

// Standard normal: mean 0 (se 1e-3 at n = 1e6), variance 1 (se sqrt(2/n) = 1.4e-3).
TEST(Random, NormalMoments) {
  Rng rng(9);
  const int n = 1000000;
  double s = 0, s2 = 0;
  for (int i = 0; i < n; ++i) {
    const double z = rng.normal();
    s += z;
    s2 += z * z;
  }
  EXPECT_NEAR(s / n, 0.0, 5e-3);
  EXPECT_NEAR(s2 / n, 1.0, 7e-3);
}

}  // namespace shockgas
