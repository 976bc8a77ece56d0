// The least a whole process computing the sticky gas at one time must do, as a
// baseline for `shockgas run` with solver = "hull" (bench/hull_command.sh):
// draw the bodies of a white-noise scene as the command draws them (lattice,
// velocities uniform on [-1, 1], the scene's seed: InitialStream, in chunks),
// then one plain pool-adjacent-violators pass over y_i = x_i + t v_i with
// weights m_i (plain_pav.hpp, as bench/hull_bench.cpp's plain_pav; on the line).
// Prints the number of blocks.
//
//   plain_pav_command N T [SEED]
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "plain_pav.hpp"
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
  shockgas::bench::PlainPav pav(p.N);
  constexpr std::size_t kChunk = 1 << 16;
  std::vector<double> x(kChunk), v(kChunk), m(kChunk);
  while (bodies.remaining() > 0) {
    const std::size_t count = std::min(kChunk, bodies.remaining());
    bodies.next(count, x.data(), v.data(), m.data());
    for (std::size_t i = 0; i < count; ++i) pav.push(x[i] + t * v[i], m[i]);
  }
  std::printf("%zu blocks\n", pav.blocks());
  return 0;
}
