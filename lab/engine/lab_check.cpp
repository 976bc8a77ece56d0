// The native side of the check of the lab's WebAssembly build
// (tests/lab/check_wasm.js is the other): runs the cases of a file through the
// lab's C functions and prints lab_digest() after each, so that the two
// outputs, compared byte for byte, say whether both builds computed the same
// bits. A case is one line:
//   SCENE N r delta sticky line seed t_end frames budget cells
// advanced to t_end in `frames` equal steps, each with that collision budget
// (a step stopped by it is advanced again to the same time). '#' starts a comment.
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

#include "lab/engine/lab_api.hpp"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: lab_check CASES\n";
    return 2;
  }
  std::ifstream in(argv[1]);
  if (!in) {
    std::cerr << "lab_check: cannot read " << argv[1] << "\n";
    return 2;
  }
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream row(line);
    std::string scene;
    double N, r, delta, t_end, budget;
    int sticky, on_line, frames, cells;
    double seed;
    if (!(row >> scene >> N >> r >> delta >> sticky >> on_line >> seed >> t_end >> frames >> budget >>
          cells)) {
      std::cerr << "lab_check: bad case: " << line << "\n";
      return 2;
    }
    std::cout << "case " << line << "\n";
    if (lab_start(scene.c_str(), N, r, delta, sticky, on_line, seed) != 0) {
      std::cout << "error " << lab_message() << "\n";
      continue;
    }
    int code = 0, steps = 0;
    for (int k = 1; k <= frames && code != 2 && code != -1; ++k) {
      const double t = t_end * k / frames;
      do code = lab_advance(t, budget, cells), ++steps;
      while (code == 1);
    }
    std::cout << "steps " << steps << " code " << code << "\n" << (code == -1 ? lab_message() : lab_digest());
  }
  return 0;
}
