// A program built for a processor this one is not: the start-up check
// (shockgas/core/instruction_sets.cpp, linked in) must stop it before main.
#include <cstdio>

namespace {
struct Initialiser {
  Initialiser() { std::puts("a static initialiser ran"); }
} initialiser;
}  // namespace

int main() {
  std::puts("main ran");
  return 0;
}
