// The least a whole process computing the sticky gas at one time must do, as a
// baseline for `shockgas run` with solver = "hull" (bench/hull_command.sh):
// draw the bodies of a white-noise scene as the command draws them (lattice,
// velocities uniform on [-1, 1], the scene's seed: InitialStream, in chunks),
// then one plain pool-adjacent-violators pass over y_i = x_i + t v_i with
// weights m_i (bench/hull_bench.cpp's plain_pav: a stack of blocks pooled by
// weighted means, on the line; it yields neither velocities nor members).
// Prints the number of blocks.
//
//   plain_pav_command N T [SEED]
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <vector>

#include "shockgas/core/initial_condition.hpp"
#include "shockgas/core/initial_stream.hpp"

int main(int argc, char** argv) {
  if (argc < 3 || argc > 4) {
    std::fprintf(stderr, "usage: plain_pav_command N T [SEED]\n");
    return 2;
  }
  shockgas::InitialParams p;
  p.N = static_cast<std::size_t>(std::strtod(argv[1], nullptr));
  p.positions = shockgas::Positions::lattice;
  p.velocities = shockgas::Velocities::uniform;
  p.seed = argc == 4 ? std::strtoull(argv[3], nullptr, 10) : 1;
  const double t = std::strtod(argv[2], nullptr);
  shockgas::InitialStream bodies(p, 0);
  auto mean = std::make_unique_for_overwrite<double[]>(p.N);
  auto weight = std::make_unique_for_overwrite<double[]>(p.N);
  constexpr std::size_t kChunk = 1 << 16;
  std::vector<double> x(kChunk), v(kChunk), m(kChunk);
  std::size_t top = 0;
  while (bodies.remaining() > 0) {
    const std::size_t count = std::min(kChunk, bodies.remaining());
    bodies.next(count, x.data(), v.data(), m.data());
    for (std::size_t i = 0; i < count; ++i) {
      double y = x[i] + t * v[i], w = m[i];
      while (top > 0 && mean[top - 1] > y) {
        const double total = weight[top - 1] + w;
        y = (weight[top - 1] * mean[top - 1] + w * y) / total;
        w = total;
        --top;
      }
      mean[top] = y, weight[top] = w;
      ++top;
    }
  }
  std::printf("%zu blocks\n", top);
  return 0;
}
