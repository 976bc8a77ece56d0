#pragma once
// Gauss-Legendre nodes and weights on [-1, 1] (exact for degree 2n - 1), by
// Newton's method on P_n from Tricomi's initial guesses; private to compare/.
#include <cmath>
#include <numbers>
#include <vector>

namespace shockgas::compare {

struct GaussRule {
  std::vector<double> x, w;
};

inline GaussRule gauss_legendre(int n) {
  GaussRule rule;
  for (int i = 0; i < n; ++i) {
    double x = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5)), dp = 1;
    for (int iteration = 0; iteration < 100; ++iteration) {
      double p0 = 1, p1 = x;  // (j+1) P_{j+1} = (2j+1) x P_j - j P_{j-1}
      for (int j = 1; j < n; ++j) {
        const double p2 = ((2.0 * j + 1) * x * p1 - j * p0) / (j + 1.0);
        p0 = p1, p1 = p2;
      }
      dp = n * (x * p1 - p0) / (x * x - 1);
      const double step = p1 / dp;
      x -= step;
      if (std::abs(step) < 1e-16) break;
    }
    rule.x.push_back(x);
    rule.w.push_back(2.0 / ((1 - x * x) * dp * dp));
  }
  return rule;
}

}  // namespace shockgas::compare
