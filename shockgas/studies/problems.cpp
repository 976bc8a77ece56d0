// The reference problems of the work-precision charts: see problems.hpp.
#include "shockgas/studies/problems.hpp"

#include <cmath>
#include <memory>
#include <numbers>

#include "shockgas/core/error.hpp"
#include "shockgas/core/random.hpp"

namespace shockgas::studies {

namespace {

constexpr std::size_t kNoisePieces = 64;  // white noise: independent values on 64 equal cells
constexpr std::uint64_t kNoiseSeed = 20260101;

Problem riemann() {
  Problem p{"riemann", {}, 0.4, true, 1.0, 1.0};
  p.field.v0 = [](double x) { return x < 0.5 ? 1.0 : 0.0; };
  return p;
}

Problem sine(const std::string& name, double t) {
  Problem p{name, {}, t, t > 1 / (2 * std::numbers::pi), 1.5, 2.0};
  p.field.v0 = [](double x) { return 0.5 + std::sin(2 * std::numbers::pi * x); };
  return p;
}

Problem noise() {
  auto values = std::make_shared<std::vector<double>>(kNoisePieces);
  Rng rng(kNoiseSeed);
  double lo = 0, hi = 0;
  for (auto& v : *values) {
    v = rng.uniform(-1.0, 1.0);
    lo = std::min(lo, v), hi = std::max(hi, v);
  }
  Problem p{"noise", {}, 0.1, false, std::max(-lo, hi), hi - lo};
  p.field.v0 = [values](double x) {
    const auto k = static_cast<std::size_t>(std::floor(x * kNoisePieces));
    return (*values)[std::min(k, kNoisePieces - 1)];
  };
  return p;
}

}  // namespace

std::vector<Problem> reference_problems() {
  return {riemann(), sine("sine_pre", 0.1), sine("sine_post", 0.5), noise()};
}

Problem problem_by_name(const std::string& name) {
  for (auto& p : reference_problems())
    if (p.name == name) return p;
  throw InputError("bench.problem", to_text(name), "riemann, sine_pre, sine_post or noise");
}

}  // namespace shockgas::studies
